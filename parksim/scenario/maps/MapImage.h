#pragma once
// A map image's pixels, as a ROS map server reads them: the PGM (binary P5 and plain P2, 8 or
// 16 bits) and PNG (through stb_image: grey, grey with alpha, RGB, RGBA, palettes, 8 or 16
// bits) images that map_saver, slam_toolbox and Cartographer write. Each pixel becomes the mean
// of its colour channels and its opacity, both in [0, 1]. Internal to the scenario module.

#include <string>
#include <vector>

namespace parksim {

struct MapImage {
  int width = 0;
  int height = 0;
  bool has_alpha = false;
  /// Mean of the colour channels of each pixel in [0, 1] (1 white), row by row from the top
  /// row, as in the file.
  std::vector<float> shade;
  /// Opacity of each pixel in [0, 1] (1 opaque), when the image has an alpha channel.
  std::vector<float> opacity;
};

/// Reads the image at `path` (PGM or PNG, told by its first bytes). Throws Error with one line
/// naming the file (and the line, for a plain PGM) when it cannot be read, is not PGM or PNG,
/// is larger than the limits of MapLimits.h, or is truncated or holds more than its header says.
MapImage readMapImage(const std::string& path);

}  // namespace parksim
