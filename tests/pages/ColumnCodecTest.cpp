// Packed columns: base64 as RFC 4648 spells it, and every typed array back to its values.

#include "parksim/pages/ColumnCodec.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/pages/PageTestSupport.h"

namespace parksim {
namespace {

using testing::unpack;

std::string base64Of(const std::string& text) {
  return base64({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

TEST(ColumnCodecTest, Base64MatchesTheRfcVectors) {
  // RFC 4648, section 10.
  EXPECT_EQ(base64Of(""), "");
  EXPECT_EQ(base64Of("f"), "Zg==");
  EXPECT_EQ(base64Of("fo"), "Zm8=");
  EXPECT_EQ(base64Of("foo"), "Zm9v");
  EXPECT_EQ(base64Of("foob"), "Zm9vYg==");
  EXPECT_EQ(base64Of("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64Of("foobar"), "Zm9vYmFy");
  const std::vector<std::uint8_t> high = {0xFB, 0xFF, 0xBF};
  EXPECT_EQ(base64(high), "+/+/");
}

TEST(ColumnCodecTest, Float64IsExact) {
  const std::vector<double> v = {0.0, -1.5, 0.1, 1e-300, 6.02214076e23, std::nan("")};
  const nlohmann::json c = float64Column(v);
  EXPECT_EQ(c["type"], "f64");
  const std::vector<double> back = unpack(c);
  ASSERT_EQ(back.size(), v.size());
  for (std::size_t i = 0; i + 1 < v.size(); ++i) EXPECT_EQ(back[i], v[i]);
  EXPECT_TRUE(std::isnan(back.back()));
}

TEST(ColumnCodecTest, Float32RoundsToTheNearestFloat) {
  const std::vector<double> v = {0.1, 1234.5678, -3e-7};
  const std::vector<double> back = unpack(float32Column(v));
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(back[i], static_cast<double>(static_cast<float>(v[i])));
    EXPECT_NEAR(back[i], v[i], std::fabs(v[i]) * 1e-7);
  }
}

TEST(ColumnCodecTest, IntegersTakeTheSmallestArrayAboveTheirMinimum) {
  const std::vector<std::int64_t> bytes = {1000, 1254, 1100};
  const nlohmann::json u8 = integerColumn(bytes);
  EXPECT_EQ(u8["type"], "u8");
  EXPECT_EQ(u8["offset"], 1000);
  EXPECT_EQ(unpack(u8), (std::vector<double>{1000, 1254, 1100}));
  // 255 values above the minimum is the u8 missing marker: the next size up.
  const std::vector<std::int64_t> wider = {-5, 250};
  EXPECT_EQ(integerColumn(wider)["type"], "u16");
  EXPECT_EQ(unpack(integerColumn(wider)), (std::vector<double>{-5, 250}));
  const std::vector<std::int64_t> big = {0, 70000, -3};
  EXPECT_EQ(integerColumn(big)["type"], "u32");
  EXPECT_EQ(unpack(integerColumn(big)), (std::vector<double>{0, 70000, -3}));
}

TEST(ColumnCodecTest, MissingIntegersReadAsNaN) {
  const std::vector<std::int64_t> v = {7, 0, 9};
  const nlohmann::json c = integerColumn(v, {true, false, true});
  const std::vector<double> back = unpack(c);
  EXPECT_EQ(back[0], 7);
  EXPECT_TRUE(std::isnan(back[1]));
  EXPECT_EQ(back[2], 9);
  EXPECT_EQ(c["offset"], 7);  // the minimum of the values that exist
}

TEST(ColumnCodecTest, RefusesWhatItCannotHold) {
  const std::vector<std::int64_t> wide = {0, std::int64_t{1} << 33};
  EXPECT_FALSE(fitsIntegerColumn(wide));
  EXPECT_THROW(integerColumn(wide), Error);
  const std::vector<std::int64_t> extremes = {std::numeric_limits<std::int64_t>::min(),
                                              std::numeric_limits<std::int64_t>::max()};
  EXPECT_FALSE(fitsIntegerColumn(extremes));
  EXPECT_THROW(integerColumn(std::vector<std::int64_t>{1, 2}, {true}), Error);
}

TEST(ColumnCodecTest, CodesTakeTheSmallestArrayForTheirLevels) {
  const std::vector<std::uint32_t> codes = {0, 1, 1, 0};
  EXPECT_EQ(codeColumn(codes, 2)["type"], "u8");
  EXPECT_EQ(codeColumn(codes, 256)["type"], "u8");
  EXPECT_EQ(codeColumn(codes, 257)["type"], "u16");
  EXPECT_EQ(codeColumn(codes, 70000)["type"], "u32");
  EXPECT_EQ(unpack(codeColumn(codes, 70000)), (std::vector<double>{0, 1, 1, 0}));
}

}  // namespace
}  // namespace parksim
