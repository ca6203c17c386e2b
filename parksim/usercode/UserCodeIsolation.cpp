#include "parksim/usercode/UserCodeIsolation.h"

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

#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/system/SigpipeBlocked.h"

namespace parksim {

namespace {

// A worker's answer to one task: a tag byte, the text's length (8 bytes), the text.
constexpr char kAnswer = 'A';
constexpr char kPlannerFailure = 'P';
constexpr char kControllerFailure = 'C';
constexpr char kParksimFailure = 'E';
// Bounded: a row, a verdict, an exit code; anything longer is not an answer.
constexpr std::uint64_t kMaxIsolatedAnswerBytes = 64u << 20;

bool writeAll(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, p + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Blocking read of exactly `size` bytes; false at end of file (or an error).
bool readAll(int fd, void* data, std::size_t size) {
  char* p = static_cast<char*>(data);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, p + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string signalText(int sig) {
  const char* name = sigabbrev_np(sig);
  const char* what = strsignal(sig);
  return std::string("SIG") + (name != nullptr ? name : std::to_string(sig).c_str()) +
         (what != nullptr ? std::string(", ") + what : std::string());
}

UserCodeError::Component componentOf(UserCodeWatch::Phase phase) {
  return phase == UserCodeWatch::Phase::kPlanner ? UserCodeError::Component::kPlanner
                                                 : UserCodeError::Component::kController;
}

std::string componentName(const UserCodeWatch& watch) {
  return std::string(watch.phase() == UserCodeWatch::Phase::kPlanner ? "planner " : "controller ") +
         watch.name();
}

// The worker's loop: a task index in, an answer out, until the parent closes its input.
[[noreturn]] void serve(const WatchedWorker::Work& work, UserCodeWatch& watch, int in, int out) {
  std::uint64_t task = 0;
  while (readAll(in, &task, sizeof task)) {
    watch.enter(UserCodeWatch::Phase::kParksim, "");
    char tag = kAnswer;
    std::string text;
    try {
      text = work(task, watch);
    } catch (const UserCodeError& e) {
      tag = e.component() == UserCodeError::Component::kPlanner ? kPlannerFailure
                                                                : kControllerFailure;
      text = e.what();
    } catch (const std::exception& e) {
      tag = kParksimFailure;
      text = e.what();
    } catch (...) {
      tag = kParksimFailure;
      text = "an exception that is not a std::exception";
    }
    watch.enter(UserCodeWatch::Phase::kParksim, "");
    const std::uint64_t size = text.size();
    std::fflush(stdout);
    std::fflush(stderr);
    if (!writeAll(out, &tag, 1) || !writeAll(out, &size, sizeof size) ||
        !writeAll(out, text.data(), text.size())) {
      break;  // the parent is gone
    }
  }
  std::fflush(stdout);
  std::fflush(stderr);
  // No destructors or atexit handlers of the parent's objects: they are the parent's.
  _exit(0);
}

}  // namespace

WatchedWorker::WatchedWorker(Work work, const UserCodeLimits& limits, const ForkHooks& hooks)
    : limits_(limits) {
  checkUserCodeLimits(limits);
  void* shared = mmap(nullptr, sizeof(UserCodeWatch), PROT_READ | PROT_WRITE,
                      MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (shared == MAP_FAILED) throw EnvironmentError("cannot map memory to watch user code");
  watch_ = new (shared) UserCodeWatch();
  int in[2];
  int out[2];
  if (pipe2(in, O_CLOEXEC) != 0) {
    munmap(watch_, sizeof(UserCodeWatch));
    throw EnvironmentError("cannot make a pipe to watch user code");
  }
  if (pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    munmap(watch_, sizeof(UserCodeWatch));
    throw EnvironmentError("cannot make a pipe to watch user code");
  }
  // What the parent buffered is written once, by the parent, not again by the worker.
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t parent = getpid();
  if (hooks.before) hooks.before();
  pid_ = fork();
  if (pid_ == 0) {
    // The worker: its own process group, so that a kill at a limit ends what it started too;
    // it dies with its parent (a parent killed, or ended by Ctrl-C, leaves no orphan running).
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(1);
    // A crash is a crash, whoever handles signals in the parent (AddressSanitizer's handler
    // reports a SIGSEGV and exits with status 1; an interpreter's prints a trace): the verdict
    // names the signal that ended the worker.
    for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) ::signal(sig, SIG_DFL);
    if (hooks.after_in_child) hooks.after_in_child();
    ::close(in[1]);
    ::close(out[0]);
    serve(work, *watch_, in[0], out[1]);
  }
  if (hooks.after_in_parent) hooks.after_in_parent();
  ::close(in[0]);
  ::close(out[1]);
  if (pid_ < 0) {
    ::close(in[1]);
    ::close(out[0]);
    munmap(watch_, sizeof(UserCodeWatch));
    throw EnvironmentError("cannot start a process for user code");
  }
  setpgid(pid_, pid_);  // also here: whichever runs first
  to_child_ = in[1];
  from_child_ = out[0];
  fcntl(from_child_, F_SETFL, fcntl(from_child_, F_GETFL) | O_NONBLOCK);
}

void WatchedWorker::closeInput() {
  if (to_child_ >= 0) ::close(to_child_);
  to_child_ = -1;
}

WatchedWorker::~WatchedWorker() {
  closeInput();  // an idle worker ends at end of input
  if (!dead_ && pid_ > 0) {
    // A busy worker's task is abandoned: kill it. An idle one is ending: give it a moment.
    if (busy_) ::kill(-pid_, SIGKILL);
    int status = 0;
    for (int tries = 0; waitpid(pid_, &status, busy_ ? 0 : WNOHANG) == 0 && tries < 100; ++tries) {
      usleep(2000);
    }
    if (waitpid(pid_, &status, WNOHANG) == 0) {
      ::kill(-pid_, SIGKILL);
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
    }
  }
  if (from_child_ >= 0) ::close(from_child_);
  if (watch_ != nullptr) munmap(watch_, sizeof(UserCodeWatch));
}

void WatchedWorker::start(std::uint64_t task) {
  if (!idle()) throw Error("WatchedWorker::start: the worker is busy or dead");
  watch_->enter(Phase::kParksim, "");
  last_phase_ = Phase::kParksim;
  last_beats_ = watch_->beats();
  since_ = std::chrono::steady_clock::now();
  received_.clear();
  killed_for_.clear();
  task_ = task;
  busy_ = true;
  // A worker that died while idle (killed from outside) has closed its input: the write fails
  // with EPIPE instead of killing parksim, and the next poll() reads its end and reports it.
  SigpipeBlocked blocked;
  if (!writeAll(to_child_, &task, sizeof task)) blocked.broke();
}

std::optional<WorkerResult> WatchedWorker::poll() {
  if (dead_ || !busy_) return std::nullopt;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(from_child_, buffer, sizeof buffer);
    if (n > 0) {
      received_.append(buffer, static_cast<std::size_t>(n));
      if (received_.size() >= 9) {
        std::uint64_t size = 0;
        std::memcpy(&size, received_.data() + 1, sizeof size);
        if (size > kMaxIsolatedAnswerBytes) {
          kill("sent more than 64 MB back");
          break;
        }
        if (received_.size() >= 9 + size) {
          WorkerResult r;
          r.task = task_;
          const std::string text = received_.substr(9, size);
          switch (received_.front()) {
            case kAnswer: r.answer = text; break;
            case kPlannerFailure:
              r.user_failure = UserCodeError(UserCodeError::Component::kPlanner, text);
              break;
            case kControllerFailure:
              r.user_failure = UserCodeError(UserCodeError::Component::kController, text);
              break;
            default: r.failure = text; break;
          }
          received_.erase(0, 9 + size);
          busy_ = false;
          return r;
        }
      }
      continue;
    }
    if (n == 0) {  // the worker closed its end: it died
      int status = 0;
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      return died(status);
    }
    if (errno == EINTR) continue;
    break;  // EAGAIN: nothing more yet
  }
  if (killed_for_.empty()) {
    // The limits: time in a phase of user code, restarted by every sign of progress.
    const auto now = std::chrono::steady_clock::now();
    const Phase phase = watch_->phase();
    const std::uint64_t beats = watch_->beats();
    if (phase != last_phase_ || beats != last_beats_) {
      last_phase_ = phase;
      last_beats_ = beats;
      since_ = now;
      return std::nullopt;
    }
    const double waited = std::chrono::duration<double>(now - since_).count();
    if (phase == Phase::kPlanner && waited > limits_.planner_s) {
      kill("ran past its time limit of " + formatGeneral(limits_.planner_s) + " s");
    } else if (phase == Phase::kController && waited > limits_.controller_tick_s) {
      kill("gave no command within its time limit of " + formatGeneral(limits_.controller_tick_s) +
           " s");
    }
  }
  if (killed_for_.empty()) return std::nullopt;
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  return died(status);
}

WorkerResult WatchedWorker::wait() {
  if (!busy_) throw Error("WatchedWorker::wait: the worker runs no task");
  for (;;) {
    if (std::optional<WorkerResult> r = poll()) return *r;
    pollfd p{fd(), POLLIN, 0};  // busy until it answers
    ::poll(&p, 1, 50);          // wakes for the answer, or to check the limits
  }
}

void WatchedWorker::kill(const std::string& why) {
  killed_for_ = why;
  ::kill(-pid_, SIGKILL);
}

WorkerResult WatchedWorker::died(int status) {
  dead_ = true;
  busy_ = false;
  WorkerResult r;
  r.task = task_;
  const Phase phase = watch_->phase();
  if (!killed_for_.empty()) {
    if (phase == Phase::kParksim) {
      r.failure = "the episode's process " + killed_for_;
    } else {
      r.user_failure =
          UserCodeError(componentOf(phase),
                        componentName(*watch_) + " " + killed_for_ + " (its process was killed)");
    }
    return r;
  }
  // It ended without answering: a crash, or an exit from inside somebody's code.
  const std::string how = WIFSIGNALED(status) ? "crashed (" + signalText(WTERMSIG(status)) + ")"
                                              : "ended the process (exit status " +
                                                    std::to_string(WEXITSTATUS(status)) + ")";
  if (phase == Phase::kParksim) {
    r.failure = "the episode's process " + how;
  } else {
    r.user_failure = UserCodeError(componentOf(phase), componentName(*watch_) + " " + how);
  }
  return r;
}

std::string runIsolated(const std::function<std::string(UserCodeWatch&)>& work,
                        const UserCodeLimits& limits, const ForkHooks& hooks) {
  WatchedWorker worker([&](std::uint64_t, UserCodeWatch& watch) { return work(watch); }, limits,
                       hooks);
  worker.start(0);
  const WorkerResult r = worker.wait();
  if (r.answer) return *r.answer;
  if (r.user_failure) throw *r.user_failure;
  throw Error(r.failure);
}

}  // namespace parksim
