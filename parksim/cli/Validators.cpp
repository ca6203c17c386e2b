#include "parksim/cli/Validators.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "parksim/cli/TerminalText.h"

namespace parksim::cli {

namespace {

// The offending text, shown safely and not at any length.
std::string shownValue(const std::string& text) {
  constexpr std::size_t kMax = 40;
  return "'" + printable(text.size() > kMax ? text.substr(0, kMax) + "..." : text) + "'";
}

template <class T>
std::from_chars_result parseWhole(const std::string& text, T& value) {
  const char* first = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
  auto r = std::from_chars(first, text.data() + text.size(), value);
  if (r.ec == std::errc() && r.ptr != text.data() + text.size()) r.ec = std::errc::invalid_argument;
  return r;
}

}  // namespace

std::string formatBound(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

CLI::Validator realIn(double lo, double hi, bool lo_open) {
  const std::string range =
      std::string(lo_open ? "(" : "[") + formatBound(lo) + ", " + formatBound(hi) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0.0;
        // from_chars accepts "nan", "inf" and "1e999" (as out of range); say which it is.
        const auto r = parseWhole(text, value);
        if (r.ec == std::errc::invalid_argument) return "not a number: " + shownValue(text);
        if (r.ec == std::errc::result_out_of_range || !std::isfinite(value)) {
          return "must be a finite number in " + range + ", got " + shownValue(text);
        }
        if (value < lo || value > hi || (lo_open && value == lo)) {
          return "must be in " + range + ", got " + shownValue(text);
        }
        return "";
      },
      "REAL in " + range);
}

CLI::Validator integerIn(std::int64_t lo, std::int64_t hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::int64_t value = 0;
        const auto r = parseWhole(text, value);
        if (r.ec == std::errc::invalid_argument) return "not an integer: " + shownValue(text);
        if (r.ec == std::errc::result_out_of_range || value < lo || value > hi) {
          return "must be an integer in " + range + ", got " + shownValue(text);
        }
        return "";
      },
      "INT in " + range);
}

CLI::Validator unsigned64() {
  const std::string range = "[0, 18446744073709551615]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const bool negative = !text.empty() && text[0] == '-';
        const auto r = parseWhole(text, value);
        if (negative || r.ec == std::errc::result_out_of_range) {
          return "must be an integer in " + range + ", got " + shownValue(text);
        }
        if (r.ec != std::errc()) return "not an integer: " + shownValue(text);
        return "";
      },
      "UINT64");
}

}  // namespace parksim::cli
