#pragma once
// Whether the tests, and the parksim program they run, are built with the sanitizers
// (PARKSIM_SANITIZE=ON defines PARKSIM_SANITIZED for the tests, whichever the compiler).

namespace parksim::testing {

#ifdef PARKSIM_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace parksim::testing
