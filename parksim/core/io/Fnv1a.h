#pragma once
// 64-bit FNV-1a: the hash behind episode ids, world content hashes and results-row seals.
// Every byte changes the state by a bijection, so a single changed byte always changes the
// hash: a check against accidents, not against forgery.

#include <cstdint>
#include <string>
#include <string_view>

namespace parksim {

/// FNV-1a's offset basis: the hash of no bytes.
inline constexpr std::uint64_t kFnv1a64Offset = 0xcbf29ce484222325ULL;

/// 64-bit FNV-1a of `text`, continued from `h` (the hash of the bytes before it).
std::uint64_t fnv1a64(std::string_view text, std::uint64_t h = kFnv1a64Offset);

/// `h` as 16 lower-case hex digits.
std::string hex16(std::uint64_t h);

}  // namespace parksim
