#pragma once
// Which shared objects this process has mapped: for the tests that check a library is loaded
// when first used, not at start-up (they run in a death test's fresh process).

#include <gtest/gtest.h>
#include <link.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace parksim::testing {

/// Whether the process has mapped a shared object whose path contains `fragment`.
inline bool mapped(const char* fragment) {
  struct Search {
    const char* fragment;
    bool found;
  } search{fragment, false};
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        auto* s = static_cast<Search*>(data);
        if (info->dlpi_name != nullptr && std::strstr(info->dlpi_name, s->fragment) != nullptr) {
          s->found = true;
        }
        return 0;
      },
      &search);
  return search.found;
}

/// Runs `problem` in a fresh process (a death test: no library loaded by an earlier test) and
/// expects it to find nothing wrong. `problem` returns the first broken expectation, or empty;
/// the caller's test is named *DeathTest, so that GoogleTest runs it first.
inline void expectNoProblemInAFreshProcess(std::string (*problem)()) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const std::string found = problem();
        std::fprintf(stderr, "%s\n", found.empty() ? "ok" : found.c_str());
        std::exit(found.empty() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "ok");
}

}  // namespace parksim::testing
