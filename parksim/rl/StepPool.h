#pragma once
// A fork-join pool for stepping a batch: run(count, work) calls work(i) for every i, spread
// over the caller's thread and the pool's workers, and returns when all calls have.
// Reinforcement-learning loops call run() every few tens of microseconds, often faster than a
// sleeping thread wakes: workers spin for StepPoolDef::spin_s before they sleep.
//
// Item i goes to thread i % threads() first (its data stays in that core's cache), but a
// thread that has done its own items takes those nobody has started, and a worker that wakes
// after the others have claimed every item joins no more. So a worker the scheduler has not
// run yet (a machine busier than its cores) never holds up a step: the caller does its items.
// Which thread ran an item therefore depends on timing; callers whose items are independent
// (TaskBatch's tasks share nothing) get the same results whatever the thread count.

#include <cstddef>
#include <functional>
#include <memory>

namespace parksim {

struct StepPoolDef {
  /// Threads that run the work, the caller's included (>= 1).
  int threads = 1;
  /// How long an idle worker (and the caller waiting for workers) polls before it sleeps, s.
  double spin_s = 50e-6;
};

class StepPool {
 public:
  /// Starts threads - 1 workers. Throws Error when threads < 1 or spin_s is outside [0, 1].
  explicit StepPool(const StepPoolDef& def);
  /// Stops and joins the workers.
  ~StepPool();

  StepPool(const StepPool&) = delete;
  StepPool& operator=(const StepPool&) = delete;

  int threads() const;

  /// Calls work(i) once for every i in [0, count) and returns when every call has returned.
  /// When calls throw, rethrows the exception of the lowest i once all calls are done. Not
  /// reentrant: one run() at a time.
  void run(std::size_t count, const std::function<void(std::size_t)>& work);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
