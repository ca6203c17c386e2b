#pragma once
// A ROS map server map: the YAML that map_saver, nav2, slam_toolbox and Cartographer write and
// the image beside it, read as nav2's map server (map_io) reads them. Internal to the scenario
// module.
//
// The YAML: `image` (relative to the YAML's folder), `resolution` (m per pixel), `origin`
// ([x, y, yaw]: the lower-left pixel's outer corner in the world, yaw in radians
// counter-clockwise), `negate` (0/1 or false/true, default 0), `occupied_thresh` (default
// 0.65), `free_thresh` (default 0.196), `mode` (`trinary`, the default, `scale` or `raw`). Each
// pixel's shade is the mean of its colour channels in [0, 1]; its occupancy `occ` is 1 - shade
// (shade when negated). trinary: occupied above occupied_thresh, free below free_thresh, unknown
// between (an alpha channel is averaged in with the colours, as nav2 does); scale: the same, but
// between the thresholds a cost 0..100 scaled between them, and unknown where a pixel is not
// opaque; raw: the value round(255 shade), unknown outside 0..100. A cell is occupied when its
// value is at least `lethal_threshold` (costmap_2d's name and default, 100).

#include <memory>
#include <string>
#include <vector>

#include "parksim/core/geometry/OccupancyGrid.h"

namespace parksim {

/// The map at `yaml_path` as classified cells. Throws Error naming the file (and line) on
/// anything it cannot honour: a missing or unreadable image, an image that is not PGM or PNG,
/// truncated or larger than the limits, a resolution that is not a positive finite number,
/// thresholds out of order, an unknown mode. A key map_server does not read is ignored, as
/// map_server ignores it, with one line in `warnings` (when given) naming the file, line and
/// key.
std::shared_ptr<const OccupancyGrid> readRosMap(const std::string& yaml_path,
                                                int lethal_threshold = 100,
                                                std::vector<std::string>* warnings = nullptr);

}  // namespace parksim
