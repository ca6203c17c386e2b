#include "parksim/sweep/Provenance.h"

#include <unistd.h>

#include "parksim/sim/BulletBuild.h"

// Set by parksim/sweep/CMakeLists.txt on this file only, so a new commit rebuilds one file.
#ifndef PARKSIM_VERSION_STRING
#define PARKSIM_VERSION_STRING "unknown"
#endif
#ifndef PARKSIM_GIT_COMMIT
#define PARKSIM_GIT_COMMIT "unknown"
#endif
#ifndef PARKSIM_BUILD_TYPE
#define PARKSIM_BUILD_TYPE "unknown"
#endif

namespace parksim {

Provenance currentProvenance() {
  char host[256] = {};
  Provenance p;
  p.parksim_version = PARKSIM_VERSION_STRING;
  p.git_commit = PARKSIM_GIT_COMMIT;
  p.build_type = PARKSIM_BUILD_TYPE;
  p.bullet_precision = bulletPrecision();
  p.host = gethostname(host, sizeof host - 1) == 0 ? host : "unknown";
  return p;
}

void appendProvenance(const Provenance& p, nlohmann::ordered_json& row) {
  row["parksim_version"] = p.parksim_version;
  row["git_commit"] = p.git_commit;
  row["build_type"] = p.build_type;
  row["bullet_precision"] = p.bullet_precision;
  row["host"] = p.host;
}

}  // namespace parksim
