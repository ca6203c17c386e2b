#include "parksim/pipeline/UserCodeIsolation.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>

#include "parksim/core/NumberFormat.h"

namespace parksim {

namespace {

// The child's answer: a tag byte, then the text.
constexpr char kAnswer = 'A';
constexpr char kPlannerFailure = 'P';
constexpr char kControllerFailure = 'C';
constexpr char kParksimFailure = 'E';

void writeAll(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: nothing to tell
    done += static_cast<std::size_t>(n);
  }
}

std::string signalText(int sig) {
  const char* name = sigabbrev_np(sig);
  const char* what = strsignal(sig);
  return std::string("SIG") + (name != nullptr ? name : std::to_string(sig).c_str()) +
         (what != nullptr ? std::string(", ") + what : std::string());
}

const char* componentKind(UserCodeWatch::Phase phase) {
  return phase == UserCodeWatch::Phase::kPlanner ? "planner" : "controller";
}

UserCodeError::Component componentOf(UserCodeWatch::Phase phase) {
  return phase == UserCodeWatch::Phase::kPlanner ? UserCodeError::Component::kPlanner
                                                 : UserCodeError::Component::kController;
}

}  // namespace

IsolatedChild::IsolatedChild(const std::function<std::string(UserCodeWatch&)>& work,
                             const UserCodeLimits& limits)
    : limits_(limits) {
  if (!(limits.planner_s > 0.0) || !(limits.controller_tick_s > 0.0)) {
    throw Error("user code limits must be positive");
  }
  void* shared = mmap(nullptr, sizeof(UserCodeWatch), PROT_READ | PROT_WRITE,
                      MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (shared == MAP_FAILED) throw EnvironmentError("cannot map memory to watch user code");
  watch_ = new (shared) UserCodeWatch();
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    munmap(watch_, sizeof(UserCodeWatch));
    throw EnvironmentError("cannot make a pipe to watch user code");
  }
  // What the parent buffered is written once, by the parent, not again by the child.
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    munmap(watch_, sizeof(UserCodeWatch));
    throw EnvironmentError("cannot start a process for user code");
  }
  if (pid_ == 0) {
    // The child: its own process group, so that a kill at a limit ends what it started too; it
    // dies with its parent (a parent killed, or ended by Ctrl-C, leaves no orphan running).
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(1);
    ::close(fds[0]);
    std::string out;
    try {
      out = kAnswer + work(*watch_);
    } catch (const UserCodeError& e) {
      out = (e.component() == UserCodeError::Component::kPlanner ? kPlannerFailure
                                                                 : kControllerFailure) +
            std::string(e.what());
    } catch (const std::exception& e) {
      out = kParksimFailure + std::string(e.what());
    } catch (...) {
      out = kParksimFailure + std::string("an exception that is not a std::exception");
    }
    writeAll(fds[1], out);
    std::fflush(stdout);
    std::fflush(stderr);
    // No destructors or atexit handlers of the parent's objects: they are the parent's.
    _exit(0);
  }
  setpgid(pid_, pid_);  // also here: whichever runs first
  ::close(fds[1]);
  fd_ = fds[0];
  fcntl(fd_, F_SETFL, fcntl(fd_, F_GETFL) | O_NONBLOCK);
  since_ = std::chrono::steady_clock::now();
}

IsolatedChild::~IsolatedChild() {
  if (!done_ && pid_ > 0) {
    ::kill(-pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (fd_ >= 0) ::close(fd_);
  if (watch_ != nullptr) munmap(watch_, sizeof(UserCodeWatch));
}

bool IsolatedChild::poll() {
  if (done_) return true;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n > 0) {
      // Bounded: a row, a verdict, an exit code; anything past 64 MB is not an answer.
      if (received_.size() + static_cast<std::size_t>(n) > (64u << 20)) {
        kill("sent more than 64 MB back");
        break;
      }
      received_.append(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0) {  // the child closed its end: it is ending
      int status = 0;
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      finish(status);
      return true;
    }
    if (errno == EINTR) continue;
    break;  // EAGAIN: nothing more yet
  }
  if (!killed_for_.empty()) {
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    finish(status);
    return true;
  }
  // The limits: time in a phase, restarted by every sign of progress.
  const auto now = std::chrono::steady_clock::now();
  const Phase phase = watch_->phase();
  const std::uint64_t beats = watch_->beats();
  if (phase != last_phase_ || beats != last_beats_) {
    last_phase_ = phase;
    last_beats_ = beats;
    since_ = now;
    return false;
  }
  const double waited = std::chrono::duration<double>(now - since_).count();
  if (phase == Phase::kPlanner && waited > limits_.planner_s) {
    kill("ran past its time limit of " + formatGeneral(limits_.planner_s) + " s");
  } else if (phase == Phase::kController && waited > limits_.controller_tick_s) {
    kill("gave no command within its time limit of " + formatGeneral(limits_.controller_tick_s) +
         " s");
  }
  if (!killed_for_.empty()) {
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    finish(status);
    return true;
  }
  return false;
}

void IsolatedChild::kill(const std::string& why) {
  killed_for_ = why;
  ::kill(-pid_, SIGKILL);
}

void IsolatedChild::finish(int status) {
  done_ = true;
  const Phase phase = watch_->phase();
  const std::string component = std::string(componentKind(phase)) + " " + watch_->name();
  if (!killed_for_.empty()) {
    if (phase == Phase::kParksim) {
      failure_ = "the episode's process " + killed_for_;
    } else {
      user_failure_ = UserCodeError(componentOf(phase),
                                    component + " " + killed_for_ + " (its process was killed)");
    }
    return;
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !received_.empty()) {
    const std::string text = received_.substr(1);
    switch (received_.front()) {
      case kAnswer: answer_ = text; return;
      case kPlannerFailure:
        user_failure_ = UserCodeError(UserCodeError::Component::kPlanner, text);
        return;
      case kControllerFailure:
        user_failure_ = UserCodeError(UserCodeError::Component::kController, text);
        return;
      default: failure_ = text; return;
    }
  }
  // It ended without answering: a crash, or an exit from inside somebody's code.
  const std::string how = WIFSIGNALED(status) ? "crashed (" + signalText(WTERMSIG(status)) + ")"
                                              : "ended the process (exit status " +
                                                    std::to_string(WEXITSTATUS(status)) + ")";
  if (phase == Phase::kParksim) {
    failure_ = "the episode's process " + how;
  } else {
    user_failure_ = UserCodeError(componentOf(phase), component + " " + how);
  }
}

std::string runIsolated(const std::function<std::string(UserCodeWatch&)>& work,
                        const UserCodeLimits& limits) {
  IsolatedChild child(work, limits);
  while (!child.poll()) {
    pollfd p{child.fd(), POLLIN, 0};
    ::poll(&p, 1, 50);  // wakes for the answer, or to check the limits
  }
  if (child.answer()) return *child.answer();
  if (child.userCodeFailure()) throw *child.userCodeFailure();
  throw Error(child.failure());
}

}  // namespace parksim
