#pragma once
// Running an external program (ffmpeg) without a shell: no quoting issues, no output on the
// caller's terminal, and a plain result instead of an exception when the program is missing or
// fails.

#include <string>
#include <vector>

#include "parksim/core/system/ChildProcess.h"  // findExecutable

namespace parksim {

struct ProcessResult {
  bool started = false;  ///< false: the program could not be started (see error)
  int exit_code = -1;    ///< exit status; -1 when it did not exit normally
  std::string error;     ///< why it did not start or did not exit normally; empty otherwise
  bool ok() const { return started && exit_code == 0; }
};

/// Runs argv[0] (a path, see findExecutable) with the arguments argv[1..] and waits for it.
/// Standard input is /dev/null; standard output and error go to `log_path` (truncated).
ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& log_path);

}  // namespace parksim
