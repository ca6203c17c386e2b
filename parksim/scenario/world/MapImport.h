#pragma once
// A map a user already has as a world file they can read and edit (`parksim import MAP --out
// WORLD.yaml`): the map as a `map:` reference (or its obstacles written out), the lot's bounds
// from its extent, parksim's default robot and a start and a goal at two free places found in
// the map, far apart, for the user to change. The text is read back as a world before it is
// returned, so an import never writes a world that does not load.

#include <optional>
#include <string>
#include <vector>

#include "parksim/scenario/world/World.h"

namespace parksim {

struct MapImportDef {
  /// The map: a ROS map server YAML (.yaml, .yml), an SVG drawing (.svg) or a Moving AI grid
  /// (.map), told by its extension.
  std::string map;
  /// Where the world will be written: the map's path in it is relative to its folder.
  std::string world;
  /// Moving AI grids: the side of a cell, m (required for them).
  std::optional<double> cell_m;
  /// SVG drawings: metres per user unit, when the drawing's size has no unit.
  std::optional<double> scale;
  /// SVG drawings: the layers and element ids whose shapes are obstacles (none: every shape).
  std::vector<std::string> layers;
  std::vector<std::string> ids;
  /// Write the obstacles out (boxes, circles, polygons with holes) instead of referring to the
  /// map: a world without the map's files, at most 10,000 obstacles and 1 MiB of text.
  bool list_obstacles = false;
};

struct MapImport {
  std::string text;  ///< the world file
  World world;       ///< the text read back (as it will load)
  std::string kind;  ///< "ros", "svg" or "movingai"
  /// What the map's reader ignored (World::warnings), one line each.
  std::vector<std::string> warnings;
};

/// Throws Error in one line when the map cannot be read (the readers' messages), its kind is
/// not known by its extension, a Moving AI grid lacks a cell size, no free place for the robot
/// exists, or the listed obstacles exceed a world file's limits.
MapImport importMap(const MapImportDef& def);

}  // namespace parksim
