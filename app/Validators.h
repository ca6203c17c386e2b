#pragma once
// CLI11 validators with messages a user can read. CLI11's own NonNegativeNumber and
// PositiveNumber print their whole range when they reject a value, which ends at the largest
// double written out in 309 digits; these say what is wanted: "--fps: must be positive, got 0".

#include <CLI/CLI.hpp>

namespace parksim::app {

/// A number > 0.
CLI::Validator positiveNumber();
/// A number >= 0.
CLI::Validator nonNegativeNumber();

}  // namespace parksim::app
