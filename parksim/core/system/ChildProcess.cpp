#include "parksim/core/system/ChildProcess.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/system/SigpipeBlocked.h"

extern char** environ;

namespace parksim {

namespace {

// The process groups of the live ChildProcess objects, for killChildProcessGroups: process-wide
// state because the processes are (a signal ends the whole of parksim). Lock-free atomics, so a
// signal watcher may read them at any moment; a group not recorded for want of a slot still
// dies with its leader's parent (PR_SET_PDEATHSIG) and with its ChildProcess.
std::array<std::atomic<pid_t>, 256> live_groups{};

void recordGroup(pid_t group) {
  for (std::atomic<pid_t>& slot : live_groups) {
    pid_t empty = 0;
    if (slot.compare_exchange_strong(empty, group)) return;
  }
}

void forgetGroup(pid_t group) {
  for (std::atomic<pid_t>& slot : live_groups) {
    pid_t expected = group;
    if (slot.compare_exchange_strong(expected, 0)) return;
  }
}

bool isExecutableFile(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// Both ends close-on-exec: no program another thread starts meanwhile inherits them.
std::array<int, 2> makePipe(const std::string& program) {
  std::array<int, 2> fds{-1, -1};
  if (::pipe2(fds.data(), O_CLOEXEC) != 0) {
    throw Error("cannot start " + program + ": no pipe (" + std::strerror(errno) + ")");
  }
  return fds;
}

void closeFd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

void setNonBlocking(int fd) {
  if (fd >= 0) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
}

// In the child: `fd` becomes `target`, open across exec. Async-signal-safe.
bool moveFd(int fd, int target) {
  if (fd == target) return ::fcntl(fd, F_SETFD, 0) == 0;
  return ::dup2(fd, target) == target;
}

// Milliseconds until `deadline`, rounded up, at most `cap`, at least 0.
int msUntil(ChildProcess::Clock::time_point deadline, int cap) {
  const auto left = deadline - ChildProcess::Clock::now();
  if (left <= ChildProcess::Clock::duration::zero()) return 0;
  const auto ms = std::chrono::ceil<std::chrono::milliseconds>(left).count();
  return static_cast<int>(std::min<long long>(ms, cap));
}

}  // namespace

std::string findExecutable(const std::string& program) {
  if (program.empty()) return {};
  if (program.find('/') != std::string::npos) {
    return isExecutableFile(program) ? program : std::string();
  }
  const char* path_env = std::getenv("PATH");
  if (path_env == nullptr) return {};
  std::string_view rest(path_env);
  while (true) {
    const std::size_t colon = rest.find(':');
    // An empty PATH entry means the current directory.
    const std::string_view dir = rest.substr(0, colon);
    std::string candidate(dir.empty() ? std::string_view(".") : dir);
    candidate += '/';
    candidate += program;
    if (isExecutableFile(candidate)) return candidate;
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
  return {};
}

std::string ChildExit::text() const {
  if (signal != 0) {
    const char* abbrev = ::sigabbrev_np(signal);
    return "was killed by signal " + std::to_string(signal) +
           (abbrev != nullptr ? " (SIG" + std::string(abbrev) + ")" : std::string());
  }
  return "exited with status " + std::to_string(exit_code);
}

ChildProcess::ChildProcess(const ChildProcessDef& def) {
  if (def.argv.empty() || def.argv[0].empty()) throw Error("no program given");
  const std::string shown = escapeText(def.argv[0]);
  const std::string program = findExecutable(def.argv[0]);
  if (program.empty()) {
    throw Error(def.argv[0].find('/') != std::string::npos ? shown + ": not an executable file"
                                                           : shown + ": no such program in PATH");
  }
  // Everything the child needs is made before fork: between fork and exec it may only make
  // async-signal-safe calls (parksim has threads).
  std::vector<char*> args;
  args.reserve(def.argv.size() + 1);
  for (const std::string& a : def.argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int dev_null = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  if (dev_null < 0) throw Error("cannot start " + shown + ": cannot open /dev/null");
  std::array<int, 2> in{-1, -1};
  std::array<int, 2> out{-1, -1};
  std::array<int, 2> err{-1, -1};
  std::array<int, 2> exec_status{-1, -1};
  auto close_all = [&] {
    for (std::array<int, 2>* p : {&in, &out, &err, &exec_status}) {
      closeFd((*p)[0]);
      closeFd((*p)[1]);
    }
    ::close(dev_null);
  };
  try {
    if (def.pipe_stdin) in = makePipe(shown);
    if (def.pipe_stdout) out = makePipe(shown);
    err = makePipe(shown);
    exec_status = makePipe(shown);
  } catch (...) {
    close_all();
    throw;
  }

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    close_all();
    throw Error("cannot start " + shown + ": " + std::strerror(e));
  }
  if (pid == 0) {
    // Its own process group, so that it and whatever it starts are ended together.
    ::setpgid(0, 0);
    resetForkedChild(parent);
    const int child_out = def.pipe_stdout ? out[1] : err[1];
    if (!moveFd(def.pipe_stdin ? in[0] : dev_null, STDIN_FILENO) ||
        !moveFd(child_out, STDOUT_FILENO) || !moveFd(err[1], STDERR_FILENO)) {
      const int e = errno;
      (void)!::write(exec_status[1], &e, sizeof e);
      ::_exit(127);
    }
    // Whatever else parksim has open stays out of the program (best effort: Linux 5.11).
    ::close_range(3, ~0U, CLOSE_RANGE_CLOEXEC);
    ::execve(program.c_str(), args.data(), environ);
    const int e = errno;
    (void)!::write(exec_status[1], &e, sizeof e);
    ::_exit(127);
  }
  // Also here, so that the group exists before the first kill whoever runs first.
  ::setpgid(pid, pid);
  pid_ = pid;
  recordGroup(pid);
  closeFd(exec_status[1]);
  closeFd(in[0]);
  closeFd(out[1]);
  closeFd(err[1]);
  ::close(dev_null);
  stdin_fd_ = in[1];
  stdout_fd_ = out[0];
  stderr_fd_ = err[0];
  // The status pipe closes at exec (close-on-exec) or carries exec's errno.
  int exec_errno = 0;
  ssize_t got = 0;
  do {
    got = ::read(exec_status[0], &exec_errno, sizeof exec_errno);
  } while (got < 0 && errno == EINTR);
  closeFd(exec_status[0]);
  if (got == static_cast<ssize_t>(sizeof exec_errno)) {
    reap(false);
    closeFd(stdin_fd_);
    closeFd(stdout_fd_);
    closeFd(stderr_fd_);
    throw Error("cannot run " + shown + ": " + std::strerror(exec_errno));
  }
  setNonBlocking(stdin_fd_);
  setNonBlocking(stdout_fd_);
  setNonBlocking(stderr_fd_);
}

ChildProcess::~ChildProcess() {
  if (!exit_) kill();
  closeFd(stdin_fd_);
  closeFd(stdout_fd_);
  closeFd(stderr_fd_);
}

bool ChildProcess::hasExited() const {
  if (exit_) return true;
  siginfo_t info{};
  // WNOWAIT: the program stays a zombie, so its group id cannot be reused before the group is
  // killed.
  while (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) < 0) {
    if (errno != EINTR) return true;
  }
  return info.si_pid == pid_;
}

void ChildProcess::reap(bool kill_group) {
  if (exit_) return;
  if (kill_group) ::kill(-pid_, SIGKILL);
  int status = 0;
  pid_t r = 0;
  do {
    r = ::waitpid(pid_, &status, 0);
  } while (r < 0 && errno == EINTR);
  forgetGroup(pid_);
  ChildExit e;
  if (r == pid_ && WIFEXITED(status)) {
    e.exit_code = WEXITSTATUS(status);
  } else if (r == pid_ && WIFSIGNALED(status)) {
    e.signal = WTERMSIG(status);
  }
  exit_ = e;
  drainStderr();
  closeFd(stdin_fd_);
}

ChildExit ChildProcess::kill() {
  if (!exit_) reap(true);
  return *exit_;
}

void ChildProcess::closeStdin() { closeFd(stdin_fd_); }

void ChildProcess::drainStderr() {
  char buffer[4096];
  while (stderr_fd_ >= 0) {
    const ssize_t n = ::read(stderr_fd_, buffer, sizeof buffer);
    if (n > 0) {
      err_tail_.append(buffer, static_cast<std::size_t>(n));
      if (err_tail_.size() > kStderrTailBytes) {
        err_tail_.erase(0, err_tail_.size() - kStderrTailBytes);
      }
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) closeFd(stderr_fd_);  // end of file: every writer is gone
    break;                            // EAGAIN: nothing more for now
  }
}

ChildProcess::LineStatus ChildProcess::exchange(std::string_view request, std::string& line,
                                                Clock::time_point deadline,
                                                std::size_t max_line_bytes) {
  std::optional<SigpipeBlocked> sigpipe;
  if (!request.empty()) sigpipe.emplace();
  std::size_t written = 0;
  bool stdout_ended = stdout_fd_ < 0;
  while (true) {
    if (written == request.size()) {
      const std::size_t nl = out_buffer_.find('\n');
      if (nl != std::string::npos && nl <= max_line_bytes) {
        line.assign(out_buffer_, 0, nl);
        out_buffer_.erase(0, nl + 1);
        return LineStatus::kLine;
      }
      if (out_buffer_.size() > max_line_bytes) return LineStatus::kTooLong;
      if (stdout_ended) return LineStatus::kClosed;
    }
    std::array<pollfd, 3> fds{};
    nfds_t n = 0;
    const bool writing = written < request.size();
    if (writing) {
      if (stdin_fd_ < 0) return LineStatus::kClosed;
      fds[n++] = {stdin_fd_, POLLOUT, 0};
    }
    if (!stdout_ended) fds[n++] = {stdout_fd_, POLLIN, 0};
    if (stderr_fd_ >= 0) fds[n++] = {stderr_fd_, POLLIN, 0};
    const int timeout = msUntil(deadline, 50);
    const int ready = ::poll(fds.data(), n, timeout);
    if (ready < 0 && errno != EINTR) return LineStatus::kClosed;
    if (ready <= 0) {
      // Nothing to read: a program that has exited (its output held open by a process it
      // started) will never answer.
      if (hasExited()) return LineStatus::kClosed;
      if (Clock::now() >= deadline) return LineStatus::kTimeout;
      continue;
    }
    for (nfds_t i = 0; i < n; ++i) {
      if (fds[i].revents == 0) continue;
      if (fds[i].fd == stdin_fd_) {
        const ssize_t w = ::write(stdin_fd_, request.data() + written, request.size() - written);
        if (w > 0) {
          written += static_cast<std::size_t>(w);
        } else if (w < 0 && errno != EAGAIN && errno != EINTR) {
          if (errno == EPIPE) sigpipe->broke();
          closeFd(stdin_fd_);
          return LineStatus::kClosed;
        }
      } else if (fds[i].fd == stdout_fd_) {
        char buffer[65536];
        const ssize_t r = ::read(stdout_fd_, buffer, sizeof buffer);
        if (r > 0) {
          out_buffer_.append(buffer, static_cast<std::size_t>(r));
        } else if (r == 0 || (errno != EAGAIN && errno != EINTR)) {
          stdout_ended = true;
        }
      } else {
        drainStderr();
      }
    }
    if (Clock::now() >= deadline && out_buffer_.find('\n') == std::string::npos) {
      return LineStatus::kTimeout;
    }
  }
}

std::optional<ChildExit> ChildProcess::waitUntil(Clock::time_point deadline) {
  int backoff_ms = 1;
  while (!exit_) {
    if (hasExited()) {
      // Whatever it started and left behind goes with it.
      reap(true);
      break;
    }
    const int timeout = msUntil(deadline, backoff_ms);
    if (timeout == 0 && Clock::now() >= deadline) return std::nullopt;
    // Output is drained (standard output dropped: nobody asked), so a program that writes
    // while it ends never blocks on a full pipe.
    std::array<pollfd, 2> fds{};
    nfds_t n = 0;
    if (stdout_fd_ >= 0) fds[n++] = {stdout_fd_, POLLIN, 0};
    if (stderr_fd_ >= 0) fds[n++] = {stderr_fd_, POLLIN, 0};
    const int ready = ::poll(fds.data(), n, timeout);
    if (ready > 0) {
      for (nfds_t i = 0; i < n; ++i) {
        if (fds[i].revents == 0) continue;
        if (fds[i].fd == stderr_fd_) {
          drainStderr();
        } else {
          char buffer[65536];
          const ssize_t r = ::read(stdout_fd_, buffer, sizeof buffer);
          if (r == 0 || (r < 0 && errno != EAGAIN && errno != EINTR)) closeFd(stdout_fd_);
        }
      }
    } else {
      backoff_ms = std::min(backoff_ms * 2, 20);
    }
  }
  return exit_;
}

std::string ChildProcess::stderrTail() const { return err_tail_; }

std::string ChildProcess::lastErrorLine() const {
  std::string_view text(err_tail_);
  while (!text.empty()) {
    std::size_t start = text.rfind('\n');
    start = start == std::string_view::npos ? 0 : start + 1;
    std::string_view line = text.substr(start);
    text = text.substr(0, start == 0 ? 0 : start - 1);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) {
      line.remove_suffix(1);
    }
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front()))) {
      line.remove_prefix(1);
    }
    if (line.empty()) continue;
    return escapeTextShortened(line, 300);
  }
  return {};
}

void resetForkedChild(pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(127);  // the parent died before prctl took effect
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  ::signal(SIGPIPE, SIG_DFL);
  ::signal(SIGXFSZ, SIG_DFL);
}

void killChildProcessGroups() {
  for (const std::atomic<pid_t>& slot : live_groups) {
    const pid_t group = slot.load();
    if (group > 0) ::kill(-group, SIGKILL);
  }
}

}  // namespace parksim
