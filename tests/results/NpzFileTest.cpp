// The .npz writer and reader: exact values, NumPy's layout, the same bytes every time, and
// damaged archives refused with one line. NumPy itself reads the files in
// tests/results/test_records_numpy.py.

#include "parksim/results/episode/NpzFile.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

using ::testing::HasSubstr;

std::vector<DataColumn> sample() {
  const double inf = std::numeric_limits<double>::infinity();
  return {{"t", {0.0, 1.0 / 240.0, 2.0 / 240.0, 1e300}},
          {"x", {-0.0, 5e-324, -inf, 0.1}},
          {"empty", {}},
          {"nan", {std::numeric_limits<double>::quiet_NaN()}}};
}

std::string errorOf(std::string_view bytes) {
  try {
    parseNpz(bytes, "f.npz");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(NpzFile, ColumnsReadBackBitForBit) {
  const std::vector<DataColumn> in = sample();
  const std::vector<DataColumn> out = parseNpz(npzArchive(in), "f.npz");
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t c = 0; c < in.size(); ++c) {
    EXPECT_EQ(out[c].name, in[c].name);
    ASSERT_EQ(out[c].values.size(), in[c].values.size());
    for (std::size_t i = 0; i < in[c].values.size(); ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(out[c].values[i]),
                std::bit_cast<std::uint64_t>(in[c].values[i]))
          << in[c].name << "[" << i << "]";
    }
  }
}

TEST(NpzFile, SameColumnsSameBytes) { EXPECT_EQ(npzArchive(sample()), npzArchive(sample())); }

TEST(NpzFile, EntriesAreNpyArraysAsNumpyWritesThem) {
  const std::string a = npzArchive({{"pos_err", {1.0, 2.0}}});
  EXPECT_EQ(a.substr(0, 4), std::string("PK\x03\x04", 4));
  EXPECT_THAT(a, HasSubstr("pos_err.npy"));
  // Time 00:00, date 1980-01-01: no clock in the file.
  EXPECT_EQ(a.substr(10, 4), std::string("\x00\x00\x21\x00", 4));
  EXPECT_EQ(a.substr(a.size() - 22, 4), std::string("PK\x05\x06", 4));
}

TEST(NpzFile, NamesMustBeUniqueAndPlain) {
  EXPECT_THROW(npzArchive({{"a", {}}, {"a", {}}}), Error);
  EXPECT_THROW(npzArchive({{"", {}}}), Error);
  EXPECT_THROW(npzArchive({{"a/b", {}}}), Error);
}

TEST(NpzFile, DamagedArchivesAreRefusedWithOneLine) {
  const std::string good = npzArchive({{"t", {1.0, 2.0, 3.0}}});
  EXPECT_THAT(errorOf(""), HasSubstr("f.npz: not a readable .npz archive: too short"));
  EXPECT_THAT(errorOf(good.substr(0, good.size() / 2)), HasSubstr("f.npz: not a readable"));
  EXPECT_THAT(errorOf(std::string(100, 'x')), HasSubstr("no end of central directory"));
  std::string flipped = good;
  flipped[40] = static_cast<char>(flipped[40] ^ 0x55);  // inside the deflated data
  EXPECT_THAT(errorOf(flipped), HasSubstr("f.npz: t.npy: "));
  std::string lied = good;
  // The central directory's uncompressed size, made larger than the data inflates to.
  const std::size_t central = good.find("PK\x01\x02");
  lied[central + 24] = static_cast<char>(lied[central + 24] + 8);
  EXPECT_THAT(errorOf(lied), HasSubstr("f.npz: t.npy: damaged deflate data"));
}

TEST(NpzFile, EntriesMustBeNpyArrays) {
  // Arrays of other types and shapes (NumPy writes them) are refused by
  // tests/results/test_records_numpy.py.
  std::string a = npzArchive({{"t", {1.0}}});
  EXPECT_THAT(errorOf(a.replace(a.rfind("t.npy"), 5, "t.txt")), HasSubstr("not a .npy entry"));
}

}  // namespace
}  // namespace parksim
