#pragma once
// Which build produced a result: parksim's version, the git commit it was built from, the build
// type, the compiler and Bullet's floating-point precision (float and double Bullet builds give
// different trajectories). Every result file carries it (plan.json, metrics.json, bench.csv,
// summary.md) so that numbers from different builds are never compared unknowingly.

#include <string>
#include <utility>
#include <vector>

namespace parksim {

struct Provenance {
  std::string version;           ///< CMake project version, e.g. "0.1.0"
  std::string git_commit;        ///< full commit hash, or "unknown" (built outside a git tree)
  bool git_dirty = false;        ///< tracked files differed from git_commit at build time
  std::string build_type;        ///< CMAKE_BUILD_TYPE, "+asan+ubsan" appended for sanitizer builds
  std::string compiler;          ///< e.g. "GNU 12.2.0"
  std::string bullet_precision;  ///< "float" or "double"
};

/// This binary's provenance (fixed when it was built).
Provenance buildProvenance();

/// The commit shortened to 12 characters with "-dirty" appended when the tree was dirty, or
/// "unknown".
std::string shortCommit(const Provenance& p);

/// One line for `--version`: "parksim 0.1.0 (commit 0123456789ab-dirty, Release, Bullet float,
/// GNU 12.2.0)".
std::string versionLine(const Provenance& p);

/// The provenance as ordered (key, value) pairs, keys as in plan.json's "provenance" object:
/// parksim_version, git_commit, git_dirty ("true"/"false"), build_type, compiler,
/// bullet_precision. For tables and other writers that are not JSON.
std::vector<std::pair<std::string, std::string>> provenanceFields(const Provenance& p);

}  // namespace parksim
