#include "parksim/renders/image/Image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

// Every count, so both the four-pixel words and the pixels left over are checked, and nothing
// past the last pixel is written.
TEST(ImageTest, RgbaToRgbDropsAlphaOnly) {
  for (std::size_t count = 0; count <= 13; ++count) {
    std::vector<std::uint8_t> rgba(4 * count);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(3 + 7 * i);
    std::vector<std::uint8_t> rgb(3 * count + 5, 0xAB);
    rgbaToRgb(rgba.data(), rgb.data(), count);
    for (std::size_t p = 0; p < count; ++p) {
      for (std::size_t c = 0; c < 3; ++c) {
        ASSERT_EQ(rgb[3 * p + c], rgba[4 * p + c]) << count << " pixels, pixel " << p;
      }
    }
    for (std::size_t i = 3 * count; i < rgb.size(); ++i) ASSERT_EQ(rgb[i], 0xAB) << count;
  }
}

TEST(ImageTest, RgbaImageGivesItsRgb) {
  RgbaImage rgba(5, 3);
  EXPECT_EQ(rgba.pixels.size(), 60u);
  for (std::size_t i = 0; i < rgba.pixels.size(); ++i) {
    rgba.pixels[i] = static_cast<std::uint8_t>(i);
  }
  const RgbImage rgb = rgba.rgb();
  ASSERT_EQ(rgb.width, 5);
  ASSERT_EQ(rgb.height, 3);
  const Rgba8 last = rgb.at(4, 2);  // pixel 14: bytes 56, 57, 58 (59 is its alpha)
  EXPECT_EQ(last.r, 56);
  EXPECT_EQ(last.g, 57);
  EXPECT_EQ(last.b, 58);
  EXPECT_EQ(last.a, 255);
  EXPECT_THROW(RgbaImage(0, 4), Error);
  EXPECT_THROW(rgba.resize(4, -1), Error);
}

}  // namespace
}  // namespace parksim
