#include "parksim/renders/PngEncoder.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "RenderTestUtil.h"
#include "parksim/core/Error.h"

namespace parksim {
namespace {

RgbImage pattern(int w, int h) {
  RgbImage img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 3;
      img.pixels[i] = static_cast<std::uint8_t>(x * 7 + y);
      img.pixels[i + 1] = static_cast<std::uint8_t>((x / 8 + y / 8) % 2 ? 200 : 30);
      img.pixels[i + 2] = static_cast<std::uint8_t>(y * 3);
    }
  }
  return img;
}

TEST(PngEncoderTest, RoundTripsThroughStbImage) {
  const std::string dir = rendertest::outputDir("PngEncoderTest");
  const RgbImage img = pattern(173, 91);  // odd sizes: no row padding assumptions
  for (PngDeflate deflate : {PngDeflate::kZlibFast, PngDeflate::kStbDefault}) {
    const std::string path = dir + "/round_trip.png";
    writePng(path, img, deflate);
    const RgbImage back = readPng(path);
    EXPECT_EQ(back.width, img.width);
    EXPECT_EQ(back.height, img.height);
    EXPECT_EQ(back, img);
  }
}

TEST(PngEncoderTest, EncodingIsDeterministicAndCompresses) {
  const RgbImage img = pattern(640, 480);
  const std::vector<unsigned char> a = encodePng(img);
  const std::vector<unsigned char> b = encodePng(img);
  EXPECT_EQ(a, b);
  EXPECT_LT(a.size(), img.pixels.size());
  ASSERT_GE(a.size(), 8u);
  EXPECT_EQ(a[1], 'P');
  EXPECT_EQ(a[2], 'N');
  EXPECT_EQ(a[3], 'G');
}

TEST(PngEncoderTest, BadInputThrows) {
  RgbImage broken;
  EXPECT_THROW(encodePng(broken), Error);
  EXPECT_THROW(readPng("/nonexistent/x.png"), Error);
  EXPECT_THROW(writePng("/nonexistent/dir/x.png", pattern(4, 4)), Error);
}

}  // namespace
}  // namespace parksim
