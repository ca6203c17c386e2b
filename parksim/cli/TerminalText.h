#pragma once
// Text from input files, paths and options is echoed in messages. Before it reaches a terminal,
// control characters (ESC sequences could recolour or rewrite the terminal) and bytes that are
// not UTF-8 are shown as \xNN escapes; everything else passes unchanged.

#include <string>
#include <string_view>

namespace parksim::cli {

/// `text` with control characters (C0 including newlines, DEL, C1) and invalid UTF-8 bytes
/// escaped as \xNN, so the result is one printable line that still names the bytes.
std::string printable(std::string_view text);

/// As printable, line by line: the newlines stay.
std::string printableLines(std::string_view text);

}  // namespace parksim::cli
