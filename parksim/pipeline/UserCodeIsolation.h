#pragma once
// User code that can crash or hang (a plugin's or a Python object's planner or controller) runs
// in a child process: a segmentation fault, an abort or an endless loop then ends that child,
// not the sweep or the command that started it, and becomes a verdict naming the component
// (planner_error, controller_error). The child tells the parent, through memory they share,
// which component it is in and that it is making progress; the parent enforces the time limits
// and kills the child's process group when one is exceeded.
//
// Forking is safe only from a process with one thread: callers (the sweep's process runner, the
// command line) start children from their main thread, before any other thread exists.

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "parksim/core/Error.h"
#include "parksim/core/UserCodeWatch.h"

namespace parksim {

/// A child process running `work`, watched.
class IsolatedChild {
 public:
  /// Forks. The child runs work(watch) and sends back the text it returns, then ends; what it
  /// throws is sent back as a failure of parksim (its message) unless it is a UserCodeError.
  IsolatedChild(const std::function<std::string(UserCodeWatch&)>& work,
                const UserCodeLimits& limits);
  /// Kills a child still running and reaps it.
  ~IsolatedChild();
  IsolatedChild(const IsolatedChild&) = delete;
  IsolatedChild& operator=(const IsolatedChild&) = delete;

  /// The pipe to wait on (poll) for the child's answer.
  int fd() const { return fd_; }
  /// Reads what the child sent, enforces the limits; true once the child is done (answered,
  /// died, or killed at a limit) and reaped.
  bool poll();

  /// When done: the child's answer, or nothing when it failed.
  const std::optional<std::string>& answer() const { return answer_; }
  /// When done without an answer: why, as the user code's failure (planner_error or
  /// controller_error naming the component) when it died or hung in user code.
  const std::optional<UserCodeError>& userCodeFailure() const { return user_failure_; }
  /// When done without an answer and not the user code's fault: parksim's own failure (an
  /// Error the child threw, or a crash outside user code), one line.
  const std::string& failure() const { return failure_; }

 private:
  using Phase = UserCodeWatch::Phase;
  void finish(int status);
  void kill(const std::string& why);

  UserCodeLimits limits_;
  UserCodeWatch* watch_ = nullptr;  // shared with the child (mmap)
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string received_;
  bool done_ = false;
  std::string killed_for_;
  std::optional<std::string> answer_;
  std::optional<UserCodeError> user_failure_;
  std::string failure_;
  Phase last_phase_ = Phase::kParksim;
  std::uint64_t last_beats_ = 0;
  std::chrono::steady_clock::time_point since_;
};

/// Runs `work` in a child and waits for it: its answer, or throws the UserCodeError of user code
/// that died or hung, or an Error with parksim's own failure.
std::string runIsolated(const std::function<std::string(UserCodeWatch&)>& work,
                        const UserCodeLimits& limits);

}  // namespace parksim
