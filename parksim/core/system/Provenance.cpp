#include "parksim/core/system/Provenance.h"

#include "parksim/core/system/ProvenanceConfig.h"
#include "parksim/core/system/ProvenanceGit.h"

namespace parksim {

Provenance buildProvenance() {
  Provenance p;
  p.version = PARKSIM_VERSION;
  p.git_commit = PARKSIM_GIT_COMMIT;
  p.git_dirty = PARKSIM_GIT_DIRTY;
  p.build_type = PARKSIM_BUILD_TYPE;
  p.compiler = PARKSIM_COMPILER;
  p.bullet_precision = PARKSIM_BULLET_PRECISION;
  return p;
}

std::string shortCommit(const Provenance& p) {
  if (p.git_commit == "unknown") return p.git_commit;
  return p.git_commit.substr(0, 12) + (p.git_dirty ? "-dirty" : "");
}

std::string versionLine(const Provenance& p) {
  return "parksim " + p.version + " (commit " + shortCommit(p) + ", " + p.build_type + ", Bullet " +
         p.bullet_precision + ", " + p.compiler + ")";
}

std::vector<std::pair<std::string, std::string>> provenanceFields(const Provenance& p) {
  return {{"parksim_version", p.version},
          {"git_commit", p.git_commit},
          {"git_dirty", p.git_dirty ? "true" : "false"},
          {"build_type", p.build_type},
          {"compiler", p.compiler},
          {"bullet_precision", p.bullet_precision}};
}

}  // namespace parksim
