#include "parksim/renders/image/Adler32.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <vector>

namespace parksim {
namespace {

TEST(Adler32Test, EqualsZlibsAtEveryLengthAndOffset) {
  std::mt19937 rng(7);
  std::vector<unsigned char> data(20000);
  for (unsigned char& b : data) b = static_cast<unsigned char>(rng());
  for (std::size_t n = 0; n < 300; ++n) {
    for (std::size_t offset : {0u, 1u, 7u}) {
      EXPECT_EQ(adler32(1, data.data() + offset, n),
                ::adler32(1, data.data() + offset, static_cast<uInt>(n)))
          << n << " bytes at " << offset;
    }
  }
  // Long runs (past zlib's 5552-byte reduction point), chained from a running value.
  const std::uint32_t start = 0x12345678u % 65521u;
  EXPECT_EQ(adler32(start, data.data(), data.size()),
            ::adler32(start, data.data(), static_cast<uInt>(data.size())));
}

TEST(Adler32Test, AllOnesDoNotOverflow) {
  const std::vector<unsigned char> ones(1 << 20, 0xFF);
  EXPECT_EQ(adler32(1, ones.data(), ones.size()),
            ::adler32(1, ones.data(), static_cast<uInt>(ones.size())));
  std::uint32_t chained = 65520u | (65520u << 16);  // the largest state
  EXPECT_EQ(adler32(chained, ones.data(), 6000), ::adler32(chained, ones.data(), 6000));
}

}  // namespace
}  // namespace parksim
