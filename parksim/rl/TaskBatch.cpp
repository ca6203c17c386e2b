#include "parksim/rl/TaskBatch.h"

#include <algorithm>
#include <string>
#include <thread>

#include "parksim/core/io/Error.h"
#include "parksim/rl/StepPool.h"

namespace parksim {

namespace {

StepPoolDef poolDef(const TaskBatchDef& def, std::size_t count) {
  if (count == 0) throw Error("task batch: needs at least one task");
  if (count > kMaxBatchTasks) {
    throw Error("task batch: " + std::to_string(count) + " tasks, more than the limit of " +
                std::to_string(kMaxBatchTasks) + " (docs/limits.md)");
  }
  if (def.threads < 0 || def.threads > kMaxBatchThreads) {
    throw Error("task batch: threads must be in [0, " + std::to_string(kMaxBatchThreads) +
                "], got " + std::to_string(def.threads));
  }
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int wanted = def.threads == 0 ? hardware : def.threads;
  return {std::min(wanted, static_cast<int>(count)), def.spin_s};
}

}  // namespace

struct TaskBatch::Impl {
  Impl(const Scenario& scenario, const ParkingTaskDef& task, std::size_t count,
       const TaskBatchDef& def)
      : pool(poolDef(def, count)), autoreset(def.autoreset) {
    tasks.reserve(count);
    for (std::size_t i = 0; i < count; ++i) tasks.emplace_back(scenario, task);
    results.resize(count);
    starts.resize(count);
  }

  StepPool pool;
  TaskAutoreset autoreset;
  std::vector<ParkingTask> tasks;
  std::vector<TaskStep> results;
  std::vector<TaskStep> starts;  // kSameStep: what each task continues from
};

TaskBatch::TaskBatch(const Scenario& scenario, const ParkingTaskDef& task, std::size_t count,
                     const TaskBatchDef& def)
    : impl_(std::make_unique<Impl>(scenario, task, count, def)) {}

TaskBatch::~TaskBatch() = default;

std::size_t TaskBatch::size() const { return impl_->tasks.size(); }

int TaskBatch::threads() const { return impl_->pool.threads(); }

const std::vector<TaskStep>& TaskBatch::reset(
    const std::vector<std::optional<std::uint64_t>>& seeds) {
  Impl& d = *impl_;
  if (!seeds.empty() && seeds.size() != d.tasks.size()) {
    throw Error("task batch: " + std::to_string(seeds.size()) + " seeds for " +
                std::to_string(d.tasks.size()) + " tasks");
  }
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (seeds[i]) d.tasks[i].seed(*seeds[i]);
  }
  d.pool.run(d.tasks.size(), [&d](std::size_t i) {
    d.results[i] = d.tasks[i].reset();
    if (d.autoreset == TaskAutoreset::kSameStep) d.starts[i] = d.results[i];
  });
  return d.results;
}

const std::vector<TaskStep>& TaskBatch::step(std::span<const TaskAction> actions) {
  Impl& d = *impl_;
  if (actions.size() != d.tasks.size()) {
    throw Error("task batch: " + std::to_string(actions.size()) + " actions for " +
                std::to_string(d.tasks.size()) + " tasks");
  }
  for (std::size_t i = 0; i < actions.size(); ++i) {
    checkTaskAction(actions[i], static_cast<long>(i));
  }
  const bool same_step = d.autoreset == TaskAutoreset::kSameStep;
  d.pool.run(d.tasks.size(), [&d, actions, same_step](std::size_t i) {
    ParkingTask& task = d.tasks[i];
    d.results[i] = task.running() ? task.step(actions[i]) : task.reset();
    if (same_step) d.starts[i] = task.running() ? d.results[i] : task.reset();
  });
  return d.results;
}

const std::vector<TaskStep>& TaskBatch::last() const { return impl_->results; }

const std::vector<TaskStep>& TaskBatch::started() const { return impl_->starts; }

TaskAutoreset TaskBatch::autoreset() const { return impl_->autoreset; }

ParkingTask& TaskBatch::task(std::size_t i) { return impl_->tasks.at(i); }

const ParkingTask& TaskBatch::task(std::size_t i) const { return impl_->tasks.at(i); }

}  // namespace parksim
