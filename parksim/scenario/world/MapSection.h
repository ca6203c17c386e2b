#pragma once
// A world's `map:` section: obstacles from the maps users already have, next to the hand-written
// ones (docs/world-format.md, "Maps"). Each entry names its kind by key: `ros:` (a ROS map
// server YAML and its image, RosMap.h), `svg:` (a drawing, SvgMap.h) or `movingai:` (a Moving
// AI grid, MovingAiMap.h); paths are relative to the world file's folder. Grid maps become one
// compound obstacle each (GridMap.h), a drawing one obstacle per shape. Internal to the scenario
// module.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "parksim/core/model/Scenario.h"
#include "parksim/scenario/yaml/YamlField.h"

namespace parksim {

struct MapSection {
  std::vector<Obstacle> obstacles;
  std::vector<MapLayer> layers;
  /// All maps' extent in the lot (the lot's bounds when the world leaves them out), m.
  Eigen::AlignedBox2d extent;
  /// What the maps' readers ignored, one line each naming the file and line (RosMap.h,
  /// MovingAiMap.h).
  std::vector<std::string> warnings;
};

/// Reads the `map:` list. Problems are one line at the entry's field, carrying the map file's
/// own location: `w.yaml:9: map[0].ros: maps/lab.yaml:3: resolution: must be a finite number,
/// got .nan`.
MapSection readMapSection(const YamlField& list, const std::string& world_source);

}  // namespace parksim
