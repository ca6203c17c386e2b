#pragma once
// The `realism:` and `tolerance:` sections of a world file (docs/realism.md): how real the
// simulated robot is and which tracking tolerance `parksim run` holds the world to. Both are
// optional; loadWorld (scenario/world/World.h) reads them with the rest of the file.

#include "parksim/core/model/TrackingTolerance.h"
#include "parksim/realism/RealismDef.h"

namespace parksim {

struct WorldRealism {
  bool has_realism = false;
  RealismDef realism;  ///< presetRealism(preset) with the section's overrides
  bool has_tolerance = false;
  /// defaultTolerance(the world's robot) with the section's overrides
  TrackingTolerance tolerance;
};

}  // namespace parksim
