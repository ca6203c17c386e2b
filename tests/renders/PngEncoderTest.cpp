#include "parksim/renders/PngEncoder.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
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
  for (PngCompression compression : {PngCompression::kDefault, PngCompression::kSmall}) {
    const std::string path = dir + "/round_trip.png";
    writePng(path, img, compression);
    const RgbImage back = readPng(path);
    EXPECT_EQ(back.width, img.width);
    EXPECT_EQ(back.height, img.height);
    EXPECT_EQ(back, img);
  }
}

constexpr PngCompression kAll[] = {PngCompression::kDefault, PngCompression::kFast,
                                   PngCompression::kStored, PngCompression::kSmall};

TEST(PngEncoderTest, EveryCompressionRoundTrips) {
  for (PngCompression c : kAll) {
    PngEncoder encoder(c);  // one encoder, images of changing sizes
    for (const RgbImage& img :
         {pattern(1, 1), pattern(173, 91), pattern(640, 480), pattern(9, 3)}) {
      const std::string path = rendertest::outputDir("PngEncoderTest_" + std::string(toString(c))) +
                               "/" + std::to_string(img.width) + ".png";
      const std::vector<unsigned char>& bytes = encoder.encode(img);
      std::FILE* f = std::fopen(path.c_str(), "wb");
      ASSERT_NE(f, nullptr);
      std::fwrite(bytes.data(), 1, bytes.size(), f);
      std::fclose(f);
      EXPECT_EQ(readPng(path), img) << toString(c) << " " << img.width << "x" << img.height;
      EXPECT_EQ(encodePng(img, c), bytes);  // the same bytes from a fresh encoder
    }
  }
}

// What parksim wrote before it had its own encoder: stb_image_write with filter 0 and its
// deflate routed to zlib's compress2 at level 1. Built here from the PNG specification.
std::vector<unsigned char> referencePng(const RgbImage& img) {
  const std::size_t row = static_cast<std::size_t>(img.width) * 3;
  std::vector<unsigned char> filtered;
  for (int y = 0; y < img.height; ++y) {
    filtered.push_back(0);
    filtered.insert(filtered.end(), img.pixels.begin() + static_cast<long>(y * row),
                    img.pixels.begin() + static_cast<long>((y + 1) * row));
  }
  uLongf zlen = compressBound(static_cast<uLong>(filtered.size()));
  std::vector<unsigned char> z(zlen);
  EXPECT_EQ(compress2(z.data(), &zlen, filtered.data(), static_cast<uLong>(filtered.size()), 1),
            Z_OK);
  z.resize(zlen);
  std::vector<unsigned char> png = {137, 80, 78, 71, 13, 10, 26, 10};
  auto chunk = [&png](const char* tag, const std::vector<unsigned char>& data) {
    const auto n = static_cast<std::uint32_t>(data.size());
    for (int s = 24; s >= 0; s -= 8) png.push_back(static_cast<unsigned char>(n >> s));
    const std::size_t from = png.size();
    png.insert(png.end(), tag, tag + 4);
    png.insert(png.end(), data.begin(), data.end());
    const auto crc = static_cast<std::uint32_t>(
        crc32(0, png.data() + from, static_cast<uInt>(png.size() - from)));
    for (int s = 24; s >= 0; s -= 8) png.push_back(static_cast<unsigned char>(crc >> s));
  };
  std::vector<unsigned char> ihdr;
  for (std::uint32_t v :
       {static_cast<std::uint32_t>(img.width), static_cast<std::uint32_t>(img.height)}) {
    for (int s = 24; s >= 0; s -= 8) ihdr.push_back(static_cast<unsigned char>(v >> s));
  }
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
  chunk("IHDR", ihdr);
  chunk("IDAT", z);
  chunk("IEND", {});
  return png;
}

TEST(PngEncoderTest, DefaultWritesTheBytesOfZlibLevelOne) {
  for (const RgbImage& img : {pattern(640, 480), pattern(173, 91), pattern(1, 1)}) {
    EXPECT_EQ(encodePng(img), referencePng(img)) << img.width << "x" << img.height;
  }
}

TEST(PngEncoderTest, FastCompressesFlatAreasAndRepeatedRows) {
  // Flat areas and repeated rows, as in a rendered frame, with some detail.
  RgbImage img(640, 480);
  for (int y = 0; y < 480; ++y) {
    for (int x = 0; x < 640; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * 640 + x) * 3;
      const bool line = x % 64 == 0 || y % 48 == 0 || (x - y) / 3 == 40;
      img.pixels[i] = line ? 60 : 246;
      img.pixels[i + 1] = line ? 62 : 246;
      img.pixels[i + 2] = line ? 68 : 242;
    }
  }
  const std::size_t stored = encodePng(img, PngCompression::kStored).size();
  const std::size_t fast = encodePng(img, PngCompression::kFast).size();
  EXPECT_GT(stored, img.pixels.size());
  EXPECT_LT(fast, stored / 40);
}

TEST(PngEncoderTest, CompressionNamesRoundTrip) {
  for (PngCompression c : kAll) EXPECT_EQ(pngCompressionFromString(toString(c)), c);
  try {
    pngCompressionFromString("9");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "PNG compression must be default, fast, stored or small, got '9'");
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
