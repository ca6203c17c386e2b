#pragma once
// Internal to the scenario module (pulls in yaml-cpp through YamlField): the reader of a world
// file's `robot:` section, a differential drive's keys or a car's (docs/world-format.md,
// docs/cars.md), and the range check every robot: and physics: value gets.

#include <string_view>

#include "parksim/core/model/RobotDef.h"
#include "parksim/scenario/yaml/YamlField.h"

namespace parksim {

/// A robot or physics value: its sign first (the messages every reader gives), then the range
/// a real robot and a stable simulation can have (PhysicalRanges.h), with its reason.
double rangedValue(const YamlField& f, std::string_view key, bool zero_allowed = false);

/// The `robot:` section: `drive: differential` (the default) starts from the study's robot,
/// `drive: car` from midSizeCar(); each key then overrides one field. A key of the other drive
/// is refused naming it.
RobotDef readRobot(const YamlField& field);

}  // namespace parksim
