#pragma once
// An 8-bit RGB image, rows top to bottom, no padding: what the renderer reads back and the PNG
// encoder writes.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "parksim/renders/Color.h"

namespace parksim {

struct RgbImage {
  int width = 0;   ///< pixels
  int height = 0;  ///< pixels
  /// width * height * 3 bytes, row-major from the top-left pixel.
  std::vector<std::uint8_t> pixels;

  RgbImage() = default;
  RgbImage(int w, int h);

  /// Resizes (contents unspecified after a size change).
  void resize(int w, int h);

  /// Colour at column x, row y (from the top-left); alpha is 255. Throws Error when out of range.
  Rgba8 at(int x, int y) const;

  std::size_t byteSize() const { return pixels.size(); }

  friend bool operator==(const RgbImage&, const RgbImage&) = default;
};

}  // namespace parksim
