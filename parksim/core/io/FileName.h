#pragma once
// A name from an input file (a world, a parameter column) as part of a file name: a world named
// "lots/a" or "../x" must not name a folder, and two names must not share a file.

#include <cstddef>
#include <string>
#include <string_view>

namespace parksim {

/// Longest stem fileStemOf returns, bytes: with a prefix and an extension, far below the 255
/// bytes a file name may have on Linux, macOS and Windows.
inline constexpr std::size_t kMaxFileStem = 64;

/// `name` as it is when it is 1 to kMaxFileStem bytes of letters, digits, '.', '_' and '-' and
/// does not begin with '.' (so the study's files keep their names); else its first bytes with
/// every other byte as '_', then '-' and 16 hex digits of its FNV-1a hash, kMaxFileStem bytes
/// at most. Names that differ give stems that differ (but for a hash collision, or a name
/// that is itself such a stem).
std::string fileStemOf(std::string_view name);

}  // namespace parksim
