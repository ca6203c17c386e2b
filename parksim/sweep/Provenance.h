#pragma once
// Where a results row came from: the parksim build and the machine. Every row carries it, so a
// table merged from many machines still says what produced each episode.

#include <string>

#include <nlohmann/json.hpp>

namespace parksim {

struct Provenance {
  std::string parksim_version;   ///< the CMake project version
  std::string git_commit;        ///< HEAD when the build was configured ("unknown" outside git)
  std::string build_type;        ///< CMAKE_BUILD_TYPE
  std::string bullet_precision;  ///< "float" or "double"
  std::string host;              ///< gethostname()
};

/// This binary on this machine.
Provenance currentProvenance();

/// Adds parksim_version, git_commit, build_type, bullet_precision and host to `row`.
void appendProvenance(const Provenance& provenance, nlohmann::ordered_json& row);

}  // namespace parksim
