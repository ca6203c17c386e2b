#pragma once
// User code that can crash or hang (a plugin's or a Python object's planner or controller) runs
// in a worker process: a segmentation fault, an abort or an endless loop then ends that worker,
// not the sweep or the command that started it, and becomes a verdict naming the component
// (planner_error, controller_error). The worker tells its parent, through memory they share,
// which component it is in and that it is making progress (UserCodeWatch.h); the parent enforces
// the time limits and kills the worker's process group when one is exceeded.
//
// A worker runs task after task (a sweep's episodes) until its parent closes its input, so a
// sweep pays for a process once per worker, not once per episode. Workers are forked: callers
// fork from a thread that holds no lock another thread may hold (the sweep's and the command
// line's main thread).

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "parksim/core/io/Error.h"
#include "parksim/core/system/UserCodeWatch.h"

namespace parksim {

/// Called around fork() (an embedding interpreter's: Python's PyOS_BeforeFork and friends).
struct ForkHooks {
  std::function<void()> before;
  std::function<void()> after_in_parent;
  std::function<void()> after_in_child;
};

/// How one task ended.
struct WorkerResult {
  std::uint64_t task = 0;
  /// What the work returned; nothing when it failed.
  std::optional<std::string> answer;
  /// Why, when the user code failed: it died, hung past its limit, or threw a UserCodeError.
  std::optional<UserCodeError> user_failure;
  /// Why, when parksim itself failed (an Error the work threw, a crash outside user code).
  std::string failure;
};

class WatchedWorker {
 public:
  /// work(task, watch): runs in the worker; returns the text sent back.
  using Work = std::function<std::string(std::uint64_t task, UserCodeWatch& watch)>;

  /// Forks the worker, idle.
  WatchedWorker(Work work, const UserCodeLimits& limits, const ForkHooks& hooks = {});
  /// Ends the worker: closes its input, and kills what is still running.
  ~WatchedWorker();
  WatchedWorker(const WatchedWorker&) = delete;
  WatchedWorker& operator=(const WatchedWorker&) = delete;

  /// Hands the idle worker a task.
  void start(std::uint64_t task);
  bool idle() const { return !busy_ && !dead_; }
  /// Running a task: poll() will report how it ended.
  bool busy() const { return busy_; }
  /// The worker died or was killed: make another to go on.
  bool dead() const { return dead_; }
  /// The pipe to wait on (poll) for the answer of a busy worker; -1 otherwise (poll(2) skips
  /// it: a dead worker's pipe would wake every wait).
  int fd() const { return busy_ ? from_child_ : -1; }

  /// Closes the worker's input: an idle worker ends. A pool closes every worker's input before
  /// it destroys any (each worker forked later holds the earlier ones' inputs open).
  void closeInput();

  /// Reads what the worker sent and enforces the limits: the result of the task it was given,
  /// once that has ended (answered, failed, or the worker died or was killed).
  std::optional<WorkerResult> poll();
  /// poll() until the task ends: its result.
  WorkerResult wait();

 private:
  using Phase = UserCodeWatch::Phase;
  WorkerResult died(int status);
  void kill(const std::string& why);

  UserCodeLimits limits_;
  UserCodeWatch* watch_ = nullptr;  // shared with the worker (mmap)
  pid_t pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  bool busy_ = false;
  bool dead_ = false;
  std::uint64_t task_ = 0;
  std::string received_;
  std::string killed_for_;
  Phase last_phase_ = Phase::kParksim;
  std::uint64_t last_beats_ = 0;
  std::chrono::steady_clock::time_point since_;
};

/// Runs `work` once in a worker and waits for it: its answer, or throws the UserCodeError of
/// user code that died or hung, or an Error with parksim's own failure.
std::string runIsolated(const std::function<std::string(UserCodeWatch&)>& work,
                        const UserCodeLimits& limits, const ForkHooks& hooks = {});

}  // namespace parksim
