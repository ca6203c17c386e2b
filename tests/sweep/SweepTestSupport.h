#pragma once
// Test support for the sweep tests: a scratch directory per test and small specs on the study
// worlds.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include "tests/support/TestPaths.h"

namespace parksim::testing {

/// An empty directory under the build tree named after the running test.
inline std::string scratchDir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(parksim::testing::binaryDir()) /
                                    "test-out" / "sweep" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// A spec over the study's head-in world (absolute path) with `axes` appended.
inline std::string studySpec(const std::string& axes) {
  return "format: parksim-sweep/1\nname: test\nworlds: [" + sourceDir() +
         "/worlds/head_in.yaml]\n" + axes;
}

}  // namespace parksim::testing
