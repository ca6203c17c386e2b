#pragma once
// The `realism:` and `tolerance:` sections of a world file (docs/realism.md): how real the
// simulated robot is and which tracking tolerance `parksim run` holds the world to. Both are
// optional; loadScenario validates them with the rest of the file (same located messages).

#include <string>
#include <string_view>

#include "parksim/realism/RealismDef.h"
#include "parksim/sim/TrackingTolerance.h"

namespace parksim {

struct WorldRealism {
  bool has_realism = false;
  RealismDef realism;  ///< presetRealism(preset) with the section's overrides
  bool has_tolerance = false;
  TrackingTolerance tolerance;  ///< TrackingTolerance{} with the section's overrides
};

/// Reads the two sections of the world file at `path` (call after loadScenario accepted it).
/// Throws Error with `<file>:<line>: <field>: <what>` on bad values.
WorldRealism loadWorldRealism(const std::string& path);
WorldRealism parseWorldRealism(std::string_view yaml_text, const std::string& source_name);

}  // namespace parksim
