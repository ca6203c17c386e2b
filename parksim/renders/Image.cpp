#include "parksim/renders/Image.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "parksim/core/Error.h"

namespace parksim {

Rgba8 mix(const Rgba8& a, const Rgba8& b, double t) {
  t = std::clamp(t, 0.0, 1.0);
  auto lerp = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + (static_cast<double>(y) - x) * t));
  };
  return {lerp(a.r, b.r), lerp(a.g, b.g), lerp(a.b, b.b), lerp(a.a, b.a)};
}

RgbImage::RgbImage(int w, int h) { resize(w, h); }

void RgbImage::resize(int w, int h) {
  if (w <= 0 || h <= 0) {
    throw Error("image size must be positive, got " + std::to_string(w) + "x" + std::to_string(h));
  }
  width = w;
  height = h;
  pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
}

Rgba8 RgbImage::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height) {
    throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") outside a " +
                std::to_string(width) + "x" + std::to_string(height) + " image");
  }
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) *
                        3;
  return {pixels[i], pixels[i + 1], pixels[i + 2], 255};
}

}  // namespace parksim
