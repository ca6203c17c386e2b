#pragma once
// The seal of a results row: what lets `merge`, `report`, `verify` and a resumed sweep tell a
// row parksim wrote from one whose bytes changed since (a bad disk, a careless edit), and tell
// rows of one world content and one build from a mix.
//
// A row's line in results.jsonl ends with the key row_checksum: 16 hex digits of the 64-bit
// FNV-1a hash of the line's text without that key (the JSON object as written, closed by its
// '}'). FNV-1a changes with every single changed byte (each step is a bijection of the state),
// so a flipped byte anywhere in the line is always found; it is a check against accidents, not
// against forgery. results.csv carries the same value in its last column and is checked by
// being the rendering of the sealed results.jsonl row (csvRow).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace parksim {

/// The key of the seal, always the row's last.
inline constexpr std::string_view kRowChecksumKey = "row_checksum";

/// The key of the world's content hash (World::content_hash: its file's bytes and overrides).
inline constexpr std::string_view kWorldHashKey = "world_hash";

/// A row as results.jsonl holds it: its line (without the newline) and the checksum in it.
struct SealedRow {
  std::string line;
  std::string checksum;
};

/// Seals `row` (which must not hold row_checksum yet: Error otherwise).
SealedRow sealRow(const nlohmann::ordered_json& row);

/// What is wrong with the seal of one results.jsonl line, or nothing: no row_checksum as its
/// last key (not written by this parksim), or a checksum that does not match the text.
std::optional<std::string> sealProblem(std::string_view line);

/// The build that wrote a row, from its provenance keys (every one but host): "parksim 0.3.0
/// (commit 0123456789ab, Release, GNU 12.2.0, Bullet double)". Rows of one sweep share it.
std::string rowWriter(const nlohmann::ordered_json& row);

}  // namespace parksim
