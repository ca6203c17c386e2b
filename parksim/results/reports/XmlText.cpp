#include "parksim/results/reports/XmlText.h"

#include "parksim/core/io/Text.h"

#include <cstdint>

namespace parksim {

namespace {

constexpr char kHex[] = "0123456789abcdef";

void appendHex(std::string& out, const char* prefix, std::uint32_t value, int digits) {
  out += prefix;
  for (int d = digits - 1; d >= 0; --d) out += kHex[(value >> (4 * d)) & 0xF];
}

}  // namespace

std::string xmlEscaped(std::string_view text, XmlContext context) {
  const bool attribute = context == XmlContext::kAttribute;
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (std::size_t i = 0; i < text.size();) {
    std::uint32_t code = 0;
    const std::size_t n = utf8Sequence(text, i, code);
    if (n == 0) {  // not UTF-8: name the byte
      appendHex(out, "\\x", static_cast<unsigned char>(text[i]), 2);
      ++i;
      continue;
    }
    switch (code) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += attribute ? "&quot;" : "\""; break;
      case '\t': out += attribute ? "&#9;" : "\t"; break;
      case '\n': out += attribute ? "&#10;" : "\n"; break;
      case '\r': out += "&#13;"; break;
      default:
        if (code < 0x20 || code == 0x7F) {
          appendHex(out, "\\x", code, 2);
        } else if (code >= 0x80 && code <= 0x9F) {
          appendHex(out, "\\u", code, 4);
        } else if (code == 0xFFFE || code == 0xFFFF) {
          appendHex(out, "\\u", code, 4);
        } else {
          out.append(text.substr(i, n));
        }
    }
    i += n;
  }
  return out;
}

}  // namespace parksim
