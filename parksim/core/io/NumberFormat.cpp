#include "parksim/core/io/NumberFormat.h"

#include <charconv>
#include <system_error>

namespace parksim {

namespace {

// Large enough for any double in any of the formats used here (fixed notation of 1e308 with
// up to 30 decimals included).
constexpr std::size_t kBufferSize = 360;

template <typename... Args>
std::string toChars(double value, Args... args) {
  char buf[kBufferSize];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value, args...);
  if (ec != std::errc()) return "?";  // unreachable with kBufferSize; never throw while printing
  return std::string(buf, end);
}

std::string_view withoutPlus(std::string_view text) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+') {
    text.remove_prefix(1);
  }
  return text;
}

}  // namespace

std::string formatShortest(double value) { return toChars(value); }

void appendShortest(std::string& out, double value) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, ec == std::errc() ? end : buf);
}

void appendRoundTrip(std::string& out, double value) {
  char buf[64];
  const auto [end, ec] =
      std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 17);
  out.append(buf, ec == std::errc() ? end : buf);
}

std::string formatFixed(double value, int decimals) {
  if (decimals < 0) decimals = 0;
  if (decimals > 30) decimals = 30;
  return toChars(value, std::chars_format::fixed, decimals);
}

std::string formatGeneral(double value, int significant) {
  if (significant < 1) significant = 1;
  return toChars(value, std::chars_format::general, significant);
}

std::string padLeft(std::string text, std::size_t width) {
  if (text.size() < width) text.insert(0, width - text.size(), ' ');
  return text;
}

bool parseDouble(std::string_view text, double& out) {
  text = withoutPlus(text);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return false;
  out = value;
  return true;
}

bool parseInt(std::string_view text, long long& out) {
  text = withoutPlus(text);
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return false;
  out = value;
  return true;
}

}  // namespace parksim
