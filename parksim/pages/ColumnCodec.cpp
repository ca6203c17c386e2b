#include "parksim/pages/ColumnCodec.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

static_assert(std::endian::native == std::endian::little,
              "page columns are the bytes of little-endian typed arrays");

// The bytes of `values` stored as T, one after another.
template <class T, class V>
std::vector<std::uint8_t> packed(std::span<const V> values) {
  std::vector<std::uint8_t> bytes(values.size() * sizeof(T));
  for (std::size_t i = 0; i < values.size(); ++i) {
    const T v = static_cast<T>(values[i]);
    std::memcpy(bytes.data() + i * sizeof(T), &v, sizeof(T));
  }
  return bytes;
}

nlohmann::json typed(const char* type, const std::vector<std::uint8_t>& bytes) {
  return {{"type", type}, {"data", base64(bytes)}};
}

}  // namespace

std::string base64(std::span<const std::uint8_t> bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8) |
                            std::uint32_t{bytes[i + 2]};
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    std::uint32_t v = std::uint32_t{bytes[i]} << 16;
    if (rest == 2) v |= std::uint32_t{bytes[i + 1]} << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

nlohmann::json float64Column(std::span<const double> values) {
  // The doubles' own bytes: they are stored as the page reads them (little-endian).
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(values.data()),
                                            values.size_bytes());
  return {{"type", "f64"}, {"data", base64(bytes)}};
}

nlohmann::json float32Column(std::span<const double> values) {
  return typed("f32", packed<float>(values));
}

bool fitsIntegerColumn(std::span<const std::int64_t> values) {
  if (values.empty()) return true;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  // The range in unsigned arithmetic: hi - lo overflows int64 for the widest ranges.
  const std::uint64_t range = static_cast<std::uint64_t>(*hi) - static_cast<std::uint64_t>(*lo);
  return range < std::numeric_limits<std::uint32_t>::max();
}

nlohmann::json integerColumn(std::span<const std::int64_t> values,
                             const std::vector<bool>& present) {
  if (!present.empty() && present.size() != values.size()) {
    throw Error("integerColumn: present has " + std::to_string(present.size()) + " flags for " +
                std::to_string(values.size()) + " values");
  }
  if (!fitsIntegerColumn(values)) throw Error("integerColumn: the values span 2^32 or more");
  const auto exists = [&](std::size_t i) { return present.empty() || present[i]; };
  std::int64_t lo = 0;
  std::uint64_t range = 0;
  bool any = false;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!exists(i)) continue;
    lo = any ? std::min(lo, values[i]) : values[i];
    any = true;
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (exists(i)) range = std::max(range, static_cast<std::uint64_t>(values[i] - lo));
  }
  std::vector<std::uint32_t> stored(values.size());
  const auto store = [&](std::uint32_t missing) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      stored[i] = exists(i) ? static_cast<std::uint32_t>(values[i] - lo) : missing;
    }
  };
  nlohmann::json column;
  if (range < 0xFFu) {
    store(0xFFu);
    column = typed("u8", packed<std::uint8_t>(std::span<const std::uint32_t>(stored)));
    column["missing"] = 0xFFu;
  } else if (range < 0xFFFFu) {
    store(0xFFFFu);
    column = typed("u16", packed<std::uint16_t>(std::span<const std::uint32_t>(stored)));
    column["missing"] = 0xFFFFu;
  } else {
    store(0xFFFFFFFFu);
    column = typed("u32", packed<std::uint32_t>(std::span<const std::uint32_t>(stored)));
    column["missing"] = 0xFFFFFFFFu;
  }
  column["offset"] = lo;
  return column;
}

nlohmann::json codeColumn(std::span<const std::uint32_t> codes, std::uint32_t count) {
  if (count <= 0x100u) return typed("u8", packed<std::uint8_t>(codes));
  if (count <= 0x10000u) return typed("u16", packed<std::uint16_t>(codes));
  return typed("u32", packed<std::uint32_t>(codes));
}

}  // namespace parksim
