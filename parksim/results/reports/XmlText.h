#pragma once
// Text from user files (world names, failure lines, paths) on its way into an XML document.
// XML 1.0 cannot hold most control characters at all, not even as character references, and a
// consumer stops at the first byte that is not UTF-8; so both are replaced by visible escapes
// (`\x1b`, as escapeText in core/io/Text.h writes them) and the markup characters by entities.

#include <string>
#include <string_view>

namespace parksim {

/// Where escaped text goes: an attribute value (double-quoted) or element content.
enum class XmlContext {
  kAttribute,  ///< tab, line feed and carriage return as character references, so a reader's
               ///< attribute-value normalisation keeps them
  kContent,    ///< tab and line feed as they are, carriage return as a reference
};

/// `text` as well-formed XML 1.0 character data: & < > " as entities; characters XML 1.0
/// forbids (C0 controls other than tab, line feed and carriage return, U+FFFE, U+FFFF) and
/// bytes that are not valid UTF-8 as \xNN (\uFFFE, \uFFFF); DEL and the C1 controls, which XML
/// allows but no reader shows, as \xNN and \u00NN.
std::string xmlEscaped(std::string_view text, XmlContext context);

}  // namespace parksim
