#include "parksim/renders/image/RunLengthDeflate.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <vector>

namespace parksim {
namespace {

// Inflates a raw deflate stream with zlib; fails the test when zlib refuses it.
std::vector<unsigned char> inflateRaw(const std::vector<unsigned char>& in, std::size_t size) {
  std::vector<unsigned char> out(size + 1);
  z_stream zs{};
  EXPECT_EQ(inflateInit2(&zs, -15), Z_OK);
  zs.next_in = const_cast<unsigned char*>(in.data());
  zs.avail_in = static_cast<uInt>(in.size());
  zs.next_out = out.data();
  zs.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(inflate(&zs, Z_FINISH), Z_STREAM_END);
  EXPECT_EQ(zs.avail_in, 0u);  // nothing after the final block
  out.resize(zs.total_out);
  inflateEnd(&zs);
  return out;
}

std::vector<unsigned char> roundTrip(const std::vector<unsigned char>& data, std::size_t pixel,
                                     std::size_t row) {
  std::vector<unsigned char> packed = {0xAB};  // appended after what is there
  runLengthDeflate(data.data(), 0, data.size(), pixel, row, true, packed);
  EXPECT_EQ(packed[0], 0xAB);
  packed.erase(packed.begin());
  return inflateRaw(packed, data.size());
}

TEST(RunLengthDeflateTest, ZlibInflatesWhatItWrites) {
  std::mt19937 rng(3);
  for (std::size_t n : {0u, 1u, 2u, 3u, 4u, 257u, 258u, 259u, 1000u, 70000u}) {
    std::vector<unsigned char> random(n);
    for (unsigned char& b : random) b = static_cast<unsigned char>(rng());
    EXPECT_EQ(roundTrip(random, 3, 31), random) << n << " random bytes";
    const std::vector<unsigned char> flat(n, 0x5A);
    EXPECT_EQ(roundTrip(flat, 3, 31), flat) << n << " equal bytes";
  }
}

TEST(RunLengthDeflateTest, RepeatsCompressEveryLengthAndDistanceCode) {
  // An image-like buffer: rows of 1 + 3w bytes, flat runs, rows repeating the one above, and
  // rows of noise; widths give row distances across the distance codes' ranges.
  std::mt19937 rng(11);
  for (int width : {1, 2, 5, 40, 341, 2000, 10922}) {
    const std::size_t row = 1 + 3 * static_cast<std::size_t>(width);
    std::vector<unsigned char> img;
    for (int y = 0; y < 12; ++y) {
      const std::size_t start = img.size();
      img.push_back(0);
      for (int x = 0; x < width; ++x) {
        const bool noise = y % 5 == 3 || (x / 7) % 3 == 1;
        for (int c = 0; c < 3; ++c) {
          img.push_back(noise ? static_cast<unsigned char>(rng()) : static_cast<unsigned char>(c));
        }
      }
      if (y % 4 == 1) std::copy(img.end() - 2 * row, img.end() - row, img.begin() + start);
    }
    EXPECT_EQ(roundTrip(img, 3, row), img) << "width " << width;
  }
  // Flat data: 258-byte matches, about 2 bytes each.
  const std::vector<unsigned char> flat(100000, 7);
  std::vector<unsigned char> packed;
  runLengthDeflate(flat.data(), 0, flat.size(), 3, 301, true, packed);
  EXPECT_LT(packed.size(), 1000u);
}

TEST(RunLengthDeflateTest, DistancesBeyondTheWindowAreNotUsed) {
  std::vector<unsigned char> data(70000);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<unsigned char>(i * 31 % 251);
  EXPECT_EQ(roundTrip(data, 3, 40000), data);
  EXPECT_EQ(roundTrip(data, 0, 0), data);
}

// PNG frames are written band by band: each band's blocks are made on their own (matching into
// the bands before it) and put one after the other; zlib reads the whole.
TEST(RunLengthDeflateTest, BandsMadeApartMakeOneStream) {
  std::mt19937 rng(5);
  const std::size_t row = 1 + 3 * 50;
  std::vector<unsigned char> img;
  for (int y = 0; y < 40; ++y) {
    img.push_back(0);
    for (int x = 0; x < 150; ++x)
      img.push_back(y % 11 == 2 ? static_cast<unsigned char>(rng()) : 9);
  }
  std::vector<unsigned char> packed;
  std::vector<std::vector<unsigned char>> bands;
  for (std::size_t begin = 0; begin < img.size(); begin += 8 * row) {
    std::vector<unsigned char> band;
    runLengthDeflate(img.data(), begin, std::min(img.size(), begin + 8 * row), 3, row, false, band);
    // A band ends on zlib's sync-flush marker, and so on a byte boundary.
    ASSERT_GE(band.size(), 4u);
    EXPECT_EQ(std::vector<unsigned char>(band.end() - 4, band.end()),
              (std::vector<unsigned char>{0x00, 0x00, 0xFF, 0xFF}));
    packed.insert(packed.end(), band.begin(), band.end());
    bands.push_back(band);
  }
  runLengthDeflate(img.data(), img.size(), img.size(), 3, row, true, packed);  // empty, final
  EXPECT_EQ(inflateRaw(packed, img.size()), img);
  // A flat band after a flat row is a few bytes: its first row matches the row before it.
  EXPECT_LT(bands[2].size(), 40u);
}

}  // namespace
}  // namespace parksim
