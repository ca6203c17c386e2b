#pragma once
// Validators for numeric command-line options. CLI11 runs them on the text before converting
// it, so nothing out of range is ever clamped, wrapped or rounded into range: "abc" is "not a
// number", nan and inf are refused, 18446744073709551616 is out of range for a 64-bit seed, and
// every refusal states the accepted range in a short form ("must be in (0, 1000]"), never a
// type's full limits. The ranges are listed in docs/limits.md.

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace parksim::cli {

/// A finite real number in [lo, hi], or (lo, hi] when `lo_open`.
CLI::Validator realIn(double lo, double hi, bool lo_open = false);

/// A decimal integer in [lo, hi] (no sign for lo >= 0, no fraction, no exponent).
CLI::Validator integerIn(std::int64_t lo, std::int64_t hi);

/// A decimal integer in [0, 2^64 - 1] (seeds).
CLI::Validator unsigned64();

/// The short form of a bound in messages: "1000", "0.001", "1e+06".
std::string formatBound(double value);

}  // namespace parksim::cli
