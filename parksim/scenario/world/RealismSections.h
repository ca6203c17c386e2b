#pragma once
// Internal to the scenario module (pulls in yaml-cpp through YamlField): the reader of the
// realism: and tolerance: sections, called by the world reader on the top-level map.

#include "parksim/scenario/world/RealismReader.h"
#include "parksim/scenario/yaml/YamlField.h"

namespace parksim {

/// `robot` is the world's: its size scales the default tolerance (core/TrackingTolerance.h),
/// and a preset's drive is sized to it with `physics` (realism/DriveSizing.h).
WorldRealism readRealismSections(const YamlMap& top, const RobotDef& robot,
                                 const PhysicsDef& physics);

}  // namespace parksim
