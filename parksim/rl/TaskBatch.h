#pragma once
// A batch of parking tasks (rl/ParkingTask.h) stepped together in threads, for vectorised
// reinforcement learning: Python's VecParkingEnv is this class behind Gymnasium's vector API.
// Tasks are independent: each has its own world, seed and episode count, so the batch's
// results do not depend on the number of threads nor on which thread stepped a task (each
// step of a task runs whole on one thread, and tasks share nothing: each copied the Scenario).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "parksim/core/model/Scenario.h"
#include "parksim/rl/ParkingTask.h"
#include "parksim/rl/ParkingTaskDef.h"

namespace parksim {

/// Most tasks one batch holds: each has a world of its own (a Bullet world for the dynamics
/// fidelity, ~1 MB), so the count must not be able to ask for unbounded memory.
inline constexpr std::size_t kMaxBatchTasks = 4096;
/// Most threads a batch starts.
inline constexpr int kMaxBatchThreads = 256;

/// What TaskBatch::step does with a task whose episode ended.
enum class TaskAutoreset {
  /// Gymnasium's default ("next step"): the step reports the episode's last step; the next
  /// step resets the task instead of stepping it, its action ignored.
  kNextStep,
  /// Stable-Baselines3's VecEnv and Gymnasium's "same step": the task is reset within the step
  /// that ended its episode; last() reports that last step and started() the new episode.
  kSameStep,
};

struct TaskBatchDef {
  /// Threads that step the batch, the caller's included, at most kMaxBatchThreads; 0: one per
  /// hardware thread. Never more than the batch has tasks.
  int threads = 0;
  /// How long idle threads poll for the next step before they sleep, s (StepPoolDef).
  double spin_s = 50e-6;
  TaskAutoreset autoreset = TaskAutoreset::kNextStep;
};

class TaskBatch {
 public:
  /// `count` tasks (1 to kMaxBatchTasks) of the same world and definition. Throws Error on a
  /// bad definition.
  TaskBatch(const Scenario& scenario, const ParkingTaskDef& task, std::size_t count,
            const TaskBatchDef& def = {});
  ~TaskBatch();

  TaskBatch(const TaskBatch&) = delete;
  TaskBatch& operator=(const TaskBatch&) = delete;

  std::size_t size() const;
  int threads() const;

  /// Seeds task i with seeds[i] where it is set (Gymnasium's vector reset gives task i the
  /// seed s + i), then starts the next episode of every task. `seeds` is empty or has one
  /// entry per task (Error otherwise).
  const std::vector<TaskStep>& reset(const std::vector<std::optional<std::uint64_t>>& seeds);

  /// Holds actions[i] on task i for one control period. A task whose episode ended at the
  /// previous step (kNextStep), or was never started, is reset instead, its action ignored: it
  /// reports its first observation, reward 0, neither terminated nor truncated. Under
  /// kSameStep a task whose episode ends in this step is reset right after it (started()).
  /// Throws Error, before any task moves, when the number of actions is not size() or an
  /// action value is not finite (naming the task: "action 3: ...").
  const std::vector<TaskStep>& step(std::span<const TaskAction> actions);

  /// The result of every task's last reset or step.
  const std::vector<TaskStep>& last() const;
  /// kSameStep: what each task continues from after the last reset or step: where that step
  /// ended the episode (last()[i] terminated or truncated), the first step of the episode the
  /// task was reset to; otherwise the step itself. Empty steps under kNextStep.
  const std::vector<TaskStep>& started() const;
  TaskAutoreset autoreset() const;
  ParkingTask& task(std::size_t i);
  const ParkingTask& task(std::size_t i) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
