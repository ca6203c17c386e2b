#pragma once
// Numbers for a page, packed: a column of values as the bytes of a little-endian typed array
// (Float64Array, Float32Array, Uint8/16/32Array) in base64, which the page turns back into a
// typed array without parsing a number (web/common.js, `parksim.column`). A 20,000-row column
// of doubles takes 213 KB this way where JSON's shortest round-trip text takes about twice
// that, and the page decodes it in a fraction of the time JSON.parse takes.
//
// A column is a JSON object {"type": "f64" | "f32" | "u8" | "u16" | "u32", "data": "<base64>"}
// with, for unsigned integers, "offset": a number added back to every value (so that small
// integers far from zero still fit a byte or two) and "missing": the stored value that means
// "no value" (absent, so a page shows an empty cell). Floating-point columns say "no value"
// with NaN.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

/// RFC 4648 base64 (standard alphabet, '=' padding) of `bytes`: what the page's atob() reads.
std::string base64(std::span<const std::uint8_t> bytes);

/// The values as a Float64Array: exact.
nlohmann::json float64Column(std::span<const double> values);

/// The values rounded to the nearest float (7 significant digits): half the bytes, for numbers
/// a page shows and sorts but nobody reads back.
nlohmann::json float32Column(std::span<const double> values);

/// Integers as the smallest unsigned typed array that holds them all after subtracting the
/// smallest: {"type": "u8" | "u16" | "u32", "offset": min, "missing": M, "data": ...}. `present`
/// (when not empty, the same length as `values`) marks the values that exist; the others are
/// stored as M, the array type's largest value. Every value minus the smallest must fit 32 bits
/// with room for M (callers check with fitsIntegerColumn).
nlohmann::json integerColumn(std::span<const std::int64_t> values,
                             const std::vector<bool>& present = {});

/// True when integerColumn can hold `values`: max - min below 2^32 - 1.
bool fitsIntegerColumn(std::span<const std::int64_t> values);

/// Codes 0..count-1 (indices into a list of levels kept beside them) as the smallest unsigned
/// typed array for `count` levels: {"type": "u8" | "u16" | "u32", "data": ...}.
nlohmann::json codeColumn(std::span<const std::uint32_t> codes, std::uint32_t count);

}  // namespace parksim
