#pragma once
// Where the tests find the source tree, the build tree and the parksim executable, found at run
// time rather than compiled in: with no absolute paths in their compile commands, the test
// sources compile to the same objects in every clone, so a compiler cache shares them (CI
// builds a fresh clone). Each can be overridden by an environment variable of the same name.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace parksim::testing {

/// The build tree: test executables live at BUILD/tests/<module>/<name>.
inline std::string binaryDir() {
  if (const char* env = std::getenv("PARKSIM_BINARY_DIR")) return env;
  return std::filesystem::read_symlink("/proc/self/exe").parent_path().parent_path().parent_path();
}

/// The source tree, as recorded in the build tree's CMakeCache.txt.
inline std::string sourceDir() {
  if (const char* env = std::getenv("PARKSIM_SOURCE_DIR")) return env;
  const std::string cache = binaryDir() + "/CMakeCache.txt";
  std::ifstream in(cache);
  const std::string key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  }
  throw std::runtime_error("no CMAKE_HOME_DIRECTORY in " + cache +
                           " (set PARKSIM_SOURCE_DIR to the source tree)");
}

/// BUILD/test-output/NAME: where a test writes its files. Inside the build tree, so that two
/// builds testing at once on one machine (a CI clone beside a work tree) never share a directory.
inline std::filesystem::path testOutputDir(const std::string& name) {
  return std::filesystem::path(binaryDir()) / "test-output" / name;
}

/// The parksim executable of the same build.
inline std::string parksimExe() {
  if (const char* env = std::getenv("PARKSIM_EXE")) return env;
  return binaryDir() + "/app/parksim";
}

}  // namespace parksim::testing
