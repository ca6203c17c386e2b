#pragma once
// The values of `set:` axes: their canonical text (what episode ids hash, ParamMap.h), their
// column in the results table, their text for the world reader, and the generator that draws
// sampled values.
//
// The generator is specified here, not borrowed from the standard library (whose
// distributions differ between implementations): the same spec draws the same values on any
// machine, shard or Slurm task. For sample i of a spec with `samples: {seed: S}`, the axis at
// path P draws from its own stream, SplitMix64 started at the 64-bit FNV-1a hash of
// "parksim-sample/1;S;i;P" (decimal S and i): an axis's values depend on neither the other axes
// nor the order the spec lists them, and raising `count` keeps the first draws. u = (next >> 11)
// * 2^-53 is uniform in [0, 1). uniform [a, b]: a + (b - a) u; normal (mean, sd): Box-Muller,
// mean + sd sqrt(-2 ln(1 - u1)) cos(2 pi u2); choice of n values: the value at floor(n u).
// Drawn numbers are rounded to 10 significant digits (so that a last-bit difference between C
// libraries' log and cos cannot change an id) and written in their shortest round-trip form.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "parksim/sweep/spec/SweepSpec.h"

namespace parksim {

/// A number as canonical text: its shortest round-trip form ("6", "0.05", "1e-05").
std::string canonicalNumber(double value);

/// The value the spec's axis at `path` takes in sample `index` of `samples` (canonical text).
std::string drawSetValue(const SetDistribution& distribution, const SampleDef& samples,
                         std::uint64_t index, const std::string& path);

/// A canonical value as the results table holds it: a number, true or false, a list or map
/// (compact JSON), or else a string.
nlohmann::ordered_json setValueJson(const std::string& canonical);

/// A canonical value as YAML text for the world reader (ScenarioOverride::value): numbers,
/// booleans, lists and maps as they are; other text quoted, so that it stays one string.
std::string setValueYaml(const std::string& canonical);

}  // namespace parksim
