#include "parksim/core/system/Process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace parksim {

ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& log_path) {
  ProcessResult result;
  if (argv.empty()) {
    result.error = "no program given";
    return result;
  }
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  // fork + exec instead of posix_spawn, to set what the child needs before exec: it dies with
  // its parent (PR_SET_PDEATHSIG), so a killed parksim never leaves ffmpeg writing on; it gets
  // the default signal mask and dispositions back (parksim blocks SIGINT/SIGTERM while it
  // writes outputs and ignores SIGXFSZ). Only async-signal-safe calls between fork and exec.
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    result.error = std::string("cannot start ") + argv[0] + ": " + std::strerror(errno);
    return result;
  }
  if (pid == 0) {
    resetForkedChild(parent);
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || ::dup2(in, STDIN_FILENO) < 0 || ::dup2(out, STDOUT_FILENO) < 0 ||
        ::dup2(out, STDERR_FILENO) < 0) {
      ::_exit(127);
    }
    ::execve(args[0], args.data(), environ);
    ::_exit(127);
  }
  result.started = true;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      result.error = std::string("waiting for ") + argv[0] + ": " + std::strerror(errno);
      return result;
    }
  }
  if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
    // A failed exec in the child is exit status 127.
    if (result.exit_code != 0) {
      result.error = argv[0] + " exited with status " + std::to_string(result.exit_code);
    }
  } else if (WIFSIGNALED(status)) {
    result.error = argv[0] + " was killed by signal " + std::to_string(WTERMSIG(status));
  }
  return result;
}

}  // namespace parksim
