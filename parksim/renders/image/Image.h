#pragma once
// 8-bit images, rows top to bottom, no padding: RGB, what the renderer gives and the PNG encoder
// writes; RGBA, as the GL reads back, which films hand to their encoders as it is (the alpha is
// dropped there, a band at a time, only from the bands compressed).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "parksim/renders/image/Color.h"

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

struct RgbaImage {
  int width = 0;   ///< pixels
  int height = 0;  ///< pixels
  /// width * height * 4 bytes, row-major from the top-left pixel; the alpha bytes carry nothing.
  std::vector<std::uint8_t> pixels;

  RgbaImage() = default;
  RgbaImage(int w, int h);

  /// Resizes (contents unspecified after a size change).
  void resize(int w, int h);

  /// The image without its alpha.
  RgbImage rgb() const;
};

/// Rows [begin, end) of an image: what a film's frame changed (Renderer::renderChanges), so the
/// other rows need no read-back, comparison or conversion.
struct RowSpan {
  int begin = 0;
  int end = 0;
  friend bool operator==(const RowSpan&, const RowSpan&) = default;
};

/// Copies `count` pixels from RGBA `src` to RGB `dst`, dropping alpha.
void rgbaToRgb(const std::uint8_t* src, std::uint8_t* dst, std::size_t count);

}  // namespace parksim
