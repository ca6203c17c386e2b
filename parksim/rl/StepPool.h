#pragma once
// A fork-join pool for stepping a batch: run(count, work) calls work(i) for every i, spread
// over the caller's thread and the pool's workers, and returns when all calls have. Item i
// always goes to thread i % threads(), so which thread steps a task never depends on timing.
// Reinforcement-learning loops call run() every few tens of microseconds, often faster than a
// sleeping thread wakes: workers spin for StepPoolDef::spin_s before they sleep.

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
  /// Starts threads - 1 workers. Throws Error when threads < 1 or spin_s is negative.
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
