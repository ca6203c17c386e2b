#include "parksim/core/io/Fnv1a.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(Fnv1a, MatchesTheReferenceVectors) {
  // From the FNV reference (Fowler, Noll, Vo): the offset basis and FNV-1a of "a" and "foobar".
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
  EXPECT_EQ(hex16(fnv1a64("a")), "af63dc4c8601ec8c");
}

TEST(Fnv1a, ContinuesFromAnEarlierHash) {
  // Hashing in pieces is hashing the whole: what the world hash and the row seal rely on.
  EXPECT_EQ(fnv1a64("bar", fnv1a64("foo")), fnv1a64("foobar"));
  EXPECT_EQ(hex16(0), "0000000000000000");
}

}  // namespace
}  // namespace parksim
