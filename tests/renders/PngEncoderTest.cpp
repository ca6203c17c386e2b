#include "parksim/renders/image/PngEncoder.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "RenderTestUtil.h"
#include "parksim/core/io/Error.h"

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

std::vector<unsigned char> bytesOf(std::span<const unsigned char> bytes) {
  return {bytes.begin(), bytes.end()};
}

// `img` with an alpha byte after each pixel, which the PNG must not depend on.
RgbaImage withAlpha(const RgbImage& img, std::uint8_t alpha_seed) {
  RgbaImage out(img.width, img.height);
  for (std::size_t i = 0; i < static_cast<std::size_t>(img.width) * img.height; ++i) {
    std::memcpy(&out.pixels[4 * i], &img.pixels[3 * i], 3);
    out.pixels[4 * i + 3] = static_cast<std::uint8_t>(alpha_seed + i * 37);
  }
  return out;
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
      const std::vector<unsigned char> bytes = bytesOf(encoder.encode(img));
      std::FILE* f = std::fopen(path.c_str(), "wb");
      ASSERT_NE(f, nullptr);
      std::fwrite(bytes.data(), 1, bytes.size(), f);
      std::fclose(f);
      EXPECT_EQ(readPng(path), img) << toString(c) << " " << img.width << "x" << img.height;
      EXPECT_EQ(encodePng(img, c), bytes);  // the same bytes from a fresh encoder
    }
  }
}

// The zlib stream inside a PNG (one IDAT chunk, as the encoder writes), checked and inflated
// by zlib itself: the deflate data and the Adler-32 at its end.
std::vector<unsigned char> inflateIdat(const std::vector<unsigned char>& png, std::size_t raw) {
  constexpr std::size_t kIdat = 8 + 25;  // signature, IHDR chunk
  EXPECT_EQ(std::string(png.begin() + kIdat + 4, png.begin() + kIdat + 8), "IDAT");
  const std::size_t n = (std::size_t{png[kIdat]} << 24) | (std::size_t{png[kIdat + 1]} << 16) |
                        (std::size_t{png[kIdat + 2]} << 8) | png[kIdat + 3];
  std::vector<unsigned char> out(raw);
  uLongf out_len = static_cast<uLongf>(raw);
  EXPECT_EQ(uncompress(out.data(), &out_len, png.data() + kIdat + 8, static_cast<uLong>(n)), Z_OK);
  EXPECT_EQ(out_len, raw);
  return out;
}

// A film's frames: a fixed picture with a block moving across it and a counter-like change in
// the top rows, as the robot and the overlay change.
RgbImage filmFrame(int k, int height = 480) {
  // Like a render, mostly rows that repeat the row above (vertical stripes), with some detail.
  RgbImage img = pattern(640, height);
  for (int y = 0; y < height; ++y) {
    if (y % 50 == 7) continue;
    for (int x = 0; x < 640; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * 640 + x) * 3;
      img.pixels[i] = static_cast<std::uint8_t>(x / 16 * 9);
      img.pixels[i + 1] = static_cast<std::uint8_t>(x % 64 < 32 ? 230 : 60);
      img.pixels[i + 2] = 120;
    }
  }
  for (int y = 200; y < 256; ++y) {  // to the end of a band: the next matches into it
    for (int x = 10 * k; x < 10 * k + 50; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * 640 + x) * 3;
      img.pixels[i] = 240;
      img.pixels[i + 1] = 140;
      img.pixels[i + 2] = 30;
    }
  }
  img.pixels[3 * (5 * 640 + k)] ^= 0xFF;
  img.pixels[img.pixels.size() - 3 - 3 * static_cast<std::size_t>(k)] ^= 0xFF;  // the last band
  return img;
}

// The banded compressions: every frame's bytes are those a fresh encoder gives, whatever the
// encoder saw before (the same frames in another order, other sizes between), and zlib reads
// them back, checksum included. Noise of high bytes, the run-length deflate's worst case (9 bits
// a byte), fits the output's bound.
TEST(PngEncoderTest, BandedBytesDoNotDependOnTheLastImage) {
  RgbImage noise(640, 480);
  std::uint32_t x = 12345;
  for (std::uint8_t& p : noise.pixels) {
    x = x * 1664525u + 1013904223u;
    p = static_cast<std::uint8_t>(144 + (x >> 24) % 112);
  }
  // 480 rows are 15 whole bands; 470 end on a short one.
  for (const auto& [c, height] :
       {std::pair{PngCompression::kDefault, 480}, std::pair{PngCompression::kFast, 480},
        std::pair{PngCompression::kDefault, 470}, std::pair{PngCompression::kFast, 470}}) {
    SCOPED_TRACE(std::string(toString(c)) + ", " + std::to_string(height) + " rows");
    PngEncoder warm(c);
    std::vector<std::vector<unsigned char>> first;
    for (int k = 0; k < 6; ++k) first.push_back(bytesOf(warm.encode(filmFrame(k, height))));
    warm.encode(pattern(173, 91));
    const std::size_t stride = 640 * 3 + 1;
    for (int k : {5, 3, 3, 0, 4, 1, 2}) {
      const RgbImage img = filmFrame(k, height);
      const auto& expected = first[static_cast<std::size_t>(k)];
      EXPECT_EQ(bytesOf(warm.encode(img)), expected) << "frame " << k;
      EXPECT_EQ(encodePng(img, c), expected) << "frame " << k;
      const std::vector<unsigned char> raw =
          inflateIdat(expected, stride * static_cast<std::size_t>(height));
      for (int y = 0; y < height; ++y) {
        ASSERT_EQ(raw[static_cast<std::size_t>(y) * stride], 0) << "filter byte, row " << y;
        ASSERT_EQ(std::memcmp(raw.data() + static_cast<std::size_t>(y) * stride + 1,
                              img.pixels.data() + static_cast<std::size_t>(y) * 640 * 3, 640 * 3),
                  0)
            << "row " << y;
      }
    }
    const std::vector<unsigned char> noisy = bytesOf(warm.encode(noise));
    EXPECT_EQ(noisy, encodePng(noise, c));
    EXPECT_EQ(inflateIdat(noisy, (640 * 3 + 1) * 480).size(), (640u * 3 + 1) * 480);
  }
}

// An encoder that keeps no last image (a film whose frames would not fit twice in its memory
// budget) compresses every band, RGB or RGBA, and gives the bytes of one that copies bands; it
// takes no changed rows.
TEST(PngEncoderTest, AnEncoderKeepingNoLastImageGivesTheSameBytes) {
  for (PngCompression c : kAll) {
    SCOPED_TRACE(toString(c));
    PngEncoder keeping(c);
    PngEncoder not_keeping(c, false);
    EXPECT_EQ(keeping.keepsLast(), keepsLastImage(c));
    EXPECT_FALSE(not_keeping.keepsLast());
    for (int k : {0, 1, 1, 4, 2}) {
      const RgbImage rgb = filmFrame(k, 470);
      EXPECT_EQ(bytesOf(not_keeping.encode(rgb)), bytesOf(keeping.encode(rgb))) << "frame " << k;
      const RgbaImage rgba = withAlpha(rgb, 7);
      EXPECT_EQ(bytesOf(not_keeping.encode(rgba)), bytesOf(keeping.encode(rgba)))
          << "RGBA frame " << k;
    }
    const RgbaImage rgba = withAlpha(filmFrame(3, 470), 7);
    const RowSpan rows[] = {{0, 10}};
    EXPECT_THROW(not_keeping.encode(rgba, rows), Error);
  }
}

// Films hand their encoders RGBA as read back: the bytes are the RGB image's whatever the alpha,
// for every compression, on an encoder that saw RGB and RGBA images of other frames before; a
// frame that differs from the last in alpha only is still right.
TEST(PngEncoderTest, RgbaImagesGiveTheirRgbImagesBytes) {
  for (PngCompression c : kAll) {
    SCOPED_TRACE(toString(c));
    PngEncoder warm(c);
    for (int k : {0, 1, 1, 4, 2}) {
      const RgbImage rgb = filmFrame(k, 470);
      const std::vector<unsigned char> expected = encodePng(rgb, c);
      EXPECT_EQ(bytesOf(warm.encode(withAlpha(rgb, 0))), expected) << "frame " << k;
      EXPECT_EQ(bytesOf(warm.encode(withAlpha(rgb, 99))), expected) << "alpha only, " << k;
      if (k == 4) {
        EXPECT_EQ(bytesOf(warm.encode(rgb)), expected) << "RGB between";
      }
    }
    // RGBA, RGB, then the first RGBA again, alpha and all: compared with the RGBA image kept
    // from before the RGB one, it would look unchanged.
    const RgbaImage first = withAlpha(filmFrame(0, 470), 5);
    EXPECT_EQ(bytesOf(warm.encode(first)), encodePng(filmFrame(0, 470), c));
    EXPECT_EQ(bytesOf(warm.encode(filmFrame(3, 470))), encodePng(filmFrame(3, 470), c));
    EXPECT_EQ(bytesOf(warm.encode(first)), encodePng(filmFrame(0, 470), c)) << "RGBA again";
    const RgbImage odd = pattern(173, 91);
    EXPECT_EQ(bytesOf(warm.encode(withAlpha(odd, 7))), encodePng(odd, c));
    EXPECT_EQ(withAlpha(odd, 7).rgb(), odd);
  }
}

// The rows of `b` that differ from `a`'s, as sorted spans.
std::vector<RowSpan> rowsThatDiffer(const RgbImage& a, const RgbImage& b) {
  std::vector<RowSpan> spans;
  const std::size_t row = static_cast<std::size_t>(a.width) * 3;
  for (int y = 0; y < a.height; ++y) {
    const std::size_t at = static_cast<std::size_t>(y) * row;
    if (std::memcmp(a.pixels.data() + at, b.pixels.data() + at, row) == 0) continue;
    if (!spans.empty() && spans.back().end == y) {
      spans.back().end = y + 1;
    } else {
      spans.push_back({y, y + 1});
    }
  }
  return spans;
}

// `img` with alpha, where only rows `spans` hold its pixels: the others are noise, which an
// encoder told which rows changed must never read.
RgbaImage onlyRows(const RgbImage& img, const std::vector<RowSpan>& spans) {
  RgbaImage out = withAlpha(img, 3);
  std::vector<bool> valid(static_cast<std::size_t>(img.height), false);
  for (const RowSpan& s : spans) {
    for (int y = s.begin; y < s.end; ++y) valid[static_cast<std::size_t>(y)] = true;
  }
  std::uint32_t x = 777;
  for (int y = 0; y < img.height; ++y) {
    if (valid[static_cast<std::size_t>(y)]) continue;
    for (int i = 0; i < img.width * 4; ++i) {
      x = x * 1664525u + 1013904223u;
      out.pixels[static_cast<std::size_t>(y) * img.width * 4 + i] =
          static_cast<std::uint8_t>(x >> 24);
    }
  }
  return out;
}

// A film's next frame with only its changed rows valid (Renderer::renderChanges) has the bytes
// of the whole frame, whether the rows are exactly those that changed, more, or none.
TEST(PngEncoderTest, ChangedRowsGiveTheWholeFramesBytes) {
  for (PngCompression c : {PngCompression::kDefault, PngCompression::kFast}) {
    SCOPED_TRACE(toString(c));
    PngEncoder encoder(c);
    RgbImage last = filmFrame(0, 470);
    encoder.encode(withAlpha(last, 1));
    for (int k : {1, 2, 2, 4, 3, 0}) {
      const RgbImage next = filmFrame(k, 470);
      const std::vector<RowSpan> exact = rowsThatDiffer(last, next);
      if (last == next) {
        EXPECT_TRUE(exact.empty());
      }
      EXPECT_EQ(bytesOf(encoder.encode(onlyRows(next, exact), exact)), encodePng(next, c))
          << "frame " << k;
      last = next;
    }
    // More rows than changed, across band boundaries; then frame 2 in place of frame 0.
    const std::vector<RowSpan> wide = {{0, 5}, {30, 97}, {400, 470}};
    const RgbImage frame0 = filmFrame(0, 470);
    EXPECT_EQ(bytesOf(encoder.encode(onlyRows(frame0, wide), wide)), encodePng(frame0, c));
    const RgbImage frame2 = filmFrame(2, 470);
    const std::vector<RowSpan> rows = rowsThatDiffer(frame0, frame2);
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(bytesOf(encoder.encode(onlyRows(frame2, rows), rows)), encodePng(frame2, c));
  }
}

TEST(PngEncoderTest, ChangedRowsNeedTheLastImageAndSortedRows) {
  const RgbaImage frame = withAlpha(filmFrame(0, 470), 0);
  const std::vector<RowSpan> some = {{10, 20}};
  PngEncoder fresh(PngCompression::kFast);
  EXPECT_THROW(fresh.encode(frame, some), Error);  // nothing to take the other rows from
  fresh.encode(withAlpha(filmFrame(0, 480), 0));
  EXPECT_THROW(fresh.encode(frame, some), Error);  // the last image had another size
  fresh.encode(frame);
  for (const std::vector<RowSpan>& bad :
       {std::vector<RowSpan>{{20, 30}, {10, 15}}, std::vector<RowSpan>{{10, 20}, {15, 25}},
        std::vector<RowSpan>{{5, 5}}, std::vector<RowSpan>{{460, 471}},
        std::vector<RowSpan>{{-1, 3}}}) {
    EXPECT_THROW(fresh.encode(frame, bad), Error);
  }
  EXPECT_EQ(bytesOf(fresh.encode(frame, some)), encodePng(filmFrame(0, 470), PngCompression::kFast))
      << "a refused call leaves the last image usable";
  EXPECT_TRUE(keepsLastImage(PngCompression::kFast));
  EXPECT_TRUE(keepsLastImage(PngCompression::kDefault));
  for (PngCompression c : {PngCompression::kStored, PngCompression::kSmall}) {
    EXPECT_FALSE(keepsLastImage(c)) << toString(c);
    PngEncoder keeps_nothing(c);
    keeps_nothing.encode(frame);
    EXPECT_THROW(keeps_nothing.encode(frame, some), Error) << toString(c);
  }
}

// Bands cost little next to compressing the whole image as one stream at the same level: ~2 %
// on rendered frames; up to 10 % here, where the image shrinks to 3 % and each band's block
// header weighs more.
TEST(PngEncoderTest, DefaultIsAboutTheSizeOfZlibLevelOne) {
  for (const RgbImage& img : {filmFrame(3), pattern(173, 91)}) {
    std::vector<unsigned char> filtered;
    const std::size_t row = static_cast<std::size_t>(img.width) * 3;
    for (int y = 0; y < img.height; ++y) {
      filtered.push_back(0);
      filtered.insert(filtered.end(), img.pixels.begin() + static_cast<long>(y * row),
                      img.pixels.begin() + static_cast<long>((y + 1) * row));
    }
    uLongf zlen = compressBound(static_cast<uLong>(filtered.size()));
    std::vector<unsigned char> z(zlen);
    ASSERT_EQ(compress2(z.data(), &zlen, filtered.data(), static_cast<uLong>(filtered.size()), 1),
              Z_OK);
    const std::size_t png = encodePng(img).size();
    EXPECT_LT(static_cast<double>(png), 1.10 * static_cast<double>(zlen + 57))
        << img.width << "x" << img.height;
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
