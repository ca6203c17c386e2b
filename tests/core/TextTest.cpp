#include "parksim/core/io/Text.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(TextTest, JoinNamesListsChoicesForAMessage) {
  EXPECT_EQ(joinNames({}), "");
  EXPECT_EQ(joinNames({"ideal"}), "ideal");
  EXPECT_EQ(joinNames({"world", "ideal", "lab"}), "world, ideal, lab");
}

}  // namespace
}  // namespace parksim
