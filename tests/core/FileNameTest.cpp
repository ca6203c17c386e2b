// Names from input files as parts of file names (core/io/FileName.h): safe, apart, bounded.

#include "parksim/core/io/FileName.h"

#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Fnv1a.h"

namespace parksim {
namespace {

TEST(FileName, APlainNameStaysAsItIs) {
  EXPECT_EQ(fileStemOf("head_in"), "head_in");
  EXPECT_EQ(fileStemOf("set.robot.max_wheel_speed_radps"), "set.robot.max_wheel_speed_radps");
  EXPECT_EQ(fileStemOf(std::string(kMaxFileStem, 'a')), std::string(kMaxFileStem, 'a'));
}

TEST(FileName, ANameThatIsNotPlainIsReplacedAndHashed) {
  EXPECT_EQ(fileStemOf("lots/a"), "lots_a-" + hex16(fnv1a64("lots/a")));
  EXPECT_EQ(fileStemOf(".."), "_.-" + hex16(fnv1a64("..")));
  EXPECT_EQ(fileStemOf(""), "-" + hex16(fnv1a64("")));
  for (const std::string& name :
       std::vector<std::string>{"a/b", "../../etc/passwd", "<img src=x>", "a\\b", "\xc3\xa9",
                                std::string(1000, '/'), std::string(kMaxFileStem + 1, 'a')}) {
    const std::string stem = fileStemOf(name);
    EXPECT_LE(stem.size(), kMaxFileStem) << name;
    EXPECT_NE(stem.front(), '.') << name;
    EXPECT_EQ(stem.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                     "0123456789._-"),
              std::string::npos)
        << name;
  }
}

TEST(FileName, NamesThatDifferGetStemsThatDiffer) {
  // What replacing or cutting would join.
  const std::string long_a = std::string(100, 'x') + "a";
  const std::string long_b = std::string(100, 'x') + "b";
  std::set<std::string> stems;
  for (const std::string& name :
       std::vector<std::string>{"a/b", "a_b", "a\\b", "a b", long_a, long_b}) {
    stems.insert(fileStemOf(name));
  }
  EXPECT_EQ(stems.size(), 6u);
}

}  // namespace
}  // namespace parksim
