#pragma once
// 8-bit sRGB colours. Scenes carry colours as bytes so that an unlit, fully covered pixel
// reads back exactly the colour it was drawn with (tests compare bytes, not tolerances).

#include <cstdint>

namespace parksim {

struct Rgba8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  std::uint8_t a = 255;  ///< 255: opaque; lower values blend over what is already drawn

  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

constexpr Rgba8 rgb(std::uint8_t r, std::uint8_t g, std::uint8_t b) { return {r, g, b, 255}; }

constexpr Rgba8 withAlpha(Rgba8 c, std::uint8_t a) {
  c.a = a;
  return c;
}

/// Linear blend in byte space, t in [0, 1] (0: a, 1: b); alpha is blended too.
Rgba8 mix(const Rgba8& a, const Rgba8& b, double t);

}  // namespace parksim
