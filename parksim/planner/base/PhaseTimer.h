#pragma once
// Adds the wall time a scope takes to a phase total (PlanResult.h's PhaseTimes).

#include <chrono>

namespace parksim {

/// Adds the time since construction to `total` (s) when it goes out of scope.
class PhaseTimer {
 public:
  explicit PhaseTimer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~PhaseTimer() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace parksim
