#include "parksim/cli/Program.h"

#include <stdlib.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace parksim::cli {
namespace {

// llvmpipe rasterizes in the drawing thread unless the user chose its threads: the program's
// default, never over the user's word.
TEST(ProgramTest, StartProgramKeepsTheUsersLlvmpipeThreads) {
  const char* before = std::getenv("LP_NUM_THREADS");
  const std::optional<std::string> saved =
      before != nullptr ? std::optional<std::string>(before) : std::nullopt;
  ::unsetenv("LP_NUM_THREADS");
  startProgram();
  ASSERT_NE(std::getenv("LP_NUM_THREADS"), nullptr);
  EXPECT_EQ(std::string(std::getenv("LP_NUM_THREADS")), "0");

  ::setenv("LP_NUM_THREADS", "3", 1);
  startProgram();
  EXPECT_EQ(std::string(std::getenv("LP_NUM_THREADS")), "3");
  if (saved) {
    ::setenv("LP_NUM_THREADS", saved->c_str(), 1);
  } else {
    ::unsetenv("LP_NUM_THREADS");
  }
}

}  // namespace
}  // namespace parksim::cli
