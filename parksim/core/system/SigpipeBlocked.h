#pragma once

#include <pthread.h>
#include <signal.h>

namespace parksim {

// SIGPIPE blocked in this thread while it writes to another process's pipe (a program's standard
// input, a worker's tasks): a process that has exited makes the write fail with EPIPE instead of
// killing parksim. The signal the failed write raised is taken back before the mask is restored
// (unless one was pending already).
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGPIPE);
    ::pthread_sigmask(SIG_BLOCK, &set_, &old_);
    sigset_t pending;
    sigemptyset(&pending);
    ::sigpending(&pending);
    was_pending_ = sigismember(&pending, SIGPIPE) == 1;
  }
  ~SigpipeBlocked() {
    if (broke_ && !was_pending_) {
      const timespec zero{0, 0};
      ::sigtimedwait(&set_, nullptr, &zero);
    }
    ::pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlocked(const SigpipeBlocked&) = delete;
  SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;
  void broke() { broke_ = true; }

 private:
  sigset_t set_{};
  sigset_t old_{};
  bool was_pending_ = false;
  bool broke_ = false;
};

}  // namespace parksim
