#pragma once
// A Moving AI benchmark grid (`.map`: `type octile`, `height H`, `width W`, `map`, then H rows
// of W terrain letters), the format of the grid-based path-planning benchmarks. Passable: `.`,
// `G` (ground) and `S` (swamp); blocking: `@`, `O` (out of bounds), `T` (trees) and `W`
// (water, passable only from water, which a robot on the ground never is). The first row is the
// top of the map. Internal to the scenario module.

#include <memory>
#include <string>
#include <vector>

#include "parksim/core/geometry/OccupancyGrid.h"

namespace parksim {

/// The grid at `path`, its cells `cell_m` wide, its lower-left corner at `origin` (yaw
/// included). Throws Error naming the file and line on anything else: a wrong header, a row
/// of another length, a letter outside the format, fewer rows than the header says, a size
/// beyond the limits (decided from the header before the rest of the file is read). Text
/// after the header's rows is ignored, as Moving AI's readers ignore it, with one line in
/// `warnings` (when given) naming the file and its line.
std::shared_ptr<const OccupancyGrid> readMovingAiMap(const std::string& path, double cell_m,
                                                     const Pose2& origin,
                                                     std::vector<std::string>* warnings = nullptr);

}  // namespace parksim
