#pragma once
// Text from input files on its way to a terminal or a JSON file: control characters and bytes
// that are not UTF-8 are escaped, so a world file can neither drive the terminal (escape
// sequences) nor make a JSON writer throw.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace parksim {

/// Length of the valid UTF-8 sequence starting at text[i] and its code point in `code`, or 0
/// when none starts there (overlong forms, surrogates and code points past U+10FFFF are not).
std::size_t utf8Sequence(std::string_view text, std::size_t i, std::uint32_t& code);

/// True when `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past
/// U+10FFFF).
bool isValidUtf8(std::string_view text);

/// True when `text` is valid UTF-8 without control characters (C0, DEL, C1).
bool isPrintableUtf8(std::string_view text);

/// `text` with every control character and every byte that is not part of valid UTF-8
/// replaced by an escape (`\n`, `\t`, `\\x1b`, ...); printable UTF-8 passes unchanged.
std::string escapeText(std::string_view text);

/// `text` in single quotes as a POSIX shell reads it back (a ' inside as '\''): a path in a
/// script, a word of a command line.
std::string shellQuoted(std::string_view text);

/// escapeText(text) cut to at most `max_bytes` bytes at a character boundary, "..." added when
/// cut: user text (a program's error output, a command line) quoted in a one-line message.
std::string escapeTextShortened(std::string_view text, std::size_t max_bytes);

/// `names` joined by ", ": the choices an error message lists ("ideal, lab, odometry").
std::string joinNames(const std::vector<std::string>& names);

}  // namespace parksim
