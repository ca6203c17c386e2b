#pragma once
// Which shared objects this process has mapped: for the tests that check a library is loaded
// when first used, not at start-up (they run in a death test's fresh process).

#include <link.h>

#include <cstddef>
#include <cstring>

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

}  // namespace parksim::testing
