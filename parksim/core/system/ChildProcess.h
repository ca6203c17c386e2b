#pragma once
// A program parksim starts and talks to: a user's planner or controller given as a command
// (usercode/CommandPlanner.h, CommandController.h). Started without a shell (argv as given), in
// its own process group so that everything it starts can be ended with it, with pipes that are
// close-on-exec on parksim's side, so that a process started at the same time by another thread
// never holds them open.
//
// Bounded by construction: every wait has a deadline, standard error is kept as a bounded tail
// (kStderrTailBytes), a line read from standard output has a byte limit, and the destructor
// kills the whole process group and reaps the program, so no process or zombie outlives the
// object. The program also dies with the thread that started it (PR_SET_PDEATHSIG), and
// killChildProcessGroups() ends every group still running when parksim itself dies of a
// signal (cli/OutputDir.cpp and the sweep command call it before they re-raise).

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace parksim {

/// The program's path: `program` itself when it contains a '/', else the first executable
/// `program` in a directory of $PATH. Empty when there is none.
std::string findExecutable(const std::string& program);

struct ChildProcessDef {
  /// argv[0] is the program (a path, or a name looked up in $PATH by findExecutable), the rest
  /// its arguments, passed as they are.
  std::vector<std::string> argv;
  /// Standard input: a pipe parksim writes (send, exchange), or /dev/null.
  bool pipe_stdin = false;
  /// Standard output: a pipe parksim reads lines from (exchange), or joined with standard
  /// error (kept as its tail).
  bool pipe_stdout = false;
};

/// How a program ended.
struct ChildExit {
  int exit_code = -1;  ///< its exit status, or -1 when a signal ended it
  int signal = 0;      ///< the signal that ended it, or 0
  /// "exited with status 3", "was killed by signal 9 (Killed)".
  std::string text() const;
  bool success() const { return exit_code == 0; }
};

class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  /// Bytes of standard error (and of standard output when it is not a pipe) kept: the last.
  static constexpr std::size_t kStderrTailBytes = 4096;

  /// Starts the program. Throws Error with one line naming it when it cannot be found or
  /// started (no such program, not executable, exec failed, out of processes or pipes).
  explicit ChildProcess(const ChildProcessDef& def);
  /// Kills the process group and reaps the program, if still running.
  ~ChildProcess();

  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// What exchange() found.
  enum class LineStatus {
    kLine,     ///< a whole line was read (without its '\n')
    kTimeout,  ///< the deadline passed first
    kClosed,   ///< standard output ended, or standard input was closed, or the program exited
    kTooLong,  ///< the line is longer than max_line_bytes
  };

  /// Writes `request` to standard input (pipe_stdin), then reads standard output (pipe_stdout)
  /// up to the next '\n' into `line`, until `deadline`. Standard error is drained meanwhile, so
  /// a program that writes much to it never blocks. A broken pipe is kClosed, never SIGPIPE.
  LineStatus exchange(std::string_view request, std::string& line, Clock::time_point deadline,
                      std::size_t max_line_bytes);
  /// Bytes of standard output read but not yet returned as a line (a program that answered
  /// more than it was asked).
  std::size_t pendingOutput() const { return out_buffer_.size(); }

  /// Closes standard input: the program reads end of file.
  void closeStdin();
  /// Waits until the program exits or `deadline` passes, draining its output; then kills what
  /// is left of its process group and reaps it. The exit, or nothing when the deadline passed
  /// (the program is still running).
  std::optional<ChildExit> waitUntil(Clock::time_point deadline);
  /// Kills the process group (SIGKILL) and reaps the program; its exit (by signal 9 unless it
  /// had exited already). Idempotent.
  ChildExit kill();
  /// The exit once the program has been reaped.
  const std::optional<ChildExit>& exit() const { return exit_; }
  /// True once the program has exited (reaped or not).
  bool hasExited() const;

  /// The last kStderrTailBytes bytes of standard error, as written.
  std::string stderrTail() const;
  /// The last non-empty line of standard error, control bytes escaped, at most 300 bytes:
  /// what an error message quotes (a Python traceback's last line names the exception).
  std::string lastErrorLine() const;

  pid_t pid() const { return pid_; }

 private:
  void drainStderr();
  void reap(bool kill_group);

  pid_t pid_ = -1;
  int stdin_fd_ = -1;
  int stdout_fd_ = -1;
  int stderr_fd_ = -1;
  std::string out_buffer_;
  std::string err_tail_;
  std::optional<ChildExit> exit_;
};

/// In a child between fork and exec (async-signal-safe): it dies with the thread that forked it
/// (PR_SET_PDEATHSIG; it exits at once when `parent` is gone already) and gets the default
/// signal mask and the default actions of SIGPIPE and SIGXFSZ back (parksim blocks SIGINT and
/// SIGTERM in some threads and ignores SIGXFSZ; an ignored signal stays ignored across exec).
void resetForkedChild(pid_t parent);

/// Kills (SIGKILL) every process group a live ChildProcess started. Async-signal-safe: for a
/// signal watcher about to re-raise a fatal signal, so that grandchildren do not outlive
/// parksim (its children die with it anyway, PR_SET_PDEATHSIG).
void killChildProcessGroups();

}  // namespace parksim
