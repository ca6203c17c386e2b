#pragma once
// Test support: runs the parksim executable (TestPaths.h) and reads files back.

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include "tests/support/TestPaths.h"

namespace parksim::testing {

struct CliRun {
  int exit_code;    ///< -1 when the process did not exit normally
  std::string out;  ///< stdout and stderr, interleaved
};

/// Runs `PROGRAM ARGS` through the shell and waits for it.
inline CliRun runProgram(const std::string& program, const std::string& args) {
  const std::string cmd = program + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  std::string out;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, pipe)) out += buf;
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// Runs `parksim ARGS` through the shell and waits for it.
inline CliRun runParksim(const std::string& args) {
  return runProgram(parksim::testing::parksimExe(), args);
}

/// The whole file as bytes ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace parksim::testing
