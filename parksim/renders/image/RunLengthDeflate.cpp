#include "parksim/renders/image/RunLengthDeflate.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace parksim {

namespace {

constexpr std::size_t kMinMatch = 3;
constexpr std::size_t kMaxMatch = 258;
constexpr std::size_t kMaxDistance = 32768;

// RFC 1951 3.2.5: base values and extra bits of the length codes 257..285 and distance codes.
constexpr std::array<std::uint16_t, 29> kLengthBase = {3,  4,  5,  6,   7,   8,   9,   10,  11, 13,
                                                       15, 17, 19, 23,  27,  31,  35,  43,  51, 59,
                                                       67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<std::uint8_t, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr std::array<std::uint16_t, 30> kDistanceBase = {
    1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr std::array<std::uint8_t, 30> kDistanceExtra = {0, 0, 0,  0,  1,  1,  2,  2,  3,  3,
                                                         4, 4, 5,  5,  6,  6,  7,  7,  8,  8,
                                                         9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

// Huffman codes are sent most significant bit first into a stream read from the least
// significant bit: stored here reversed, ready to append.
constexpr std::uint32_t reversed(std::uint32_t code, int bits) {
  std::uint32_t r = 0;
  for (int i = 0; i < bits; ++i) r |= ((code >> i) & 1u) << (bits - 1 - i);
  return r;
}

struct Code {
  std::uint32_t bits = 0;  // the code and its extra bits, reversed code first
  int length = 0;
};

// The fixed literal/length code (RFC 1951 3.2.6) of symbol s.
constexpr Code fixedSymbol(int s) {
  if (s < 144) return {reversed(0x30 + s, 8), 8};
  if (s < 256) return {reversed(0x190 + s - 144, 9), 9};
  if (s < 280) return {reversed(s - 256, 7), 7};
  return {reversed(0xC0 + s - 280, 8), 8};
}

struct Tables {
  std::array<Code, 256> literal{};
  std::array<Code, kMaxMatch + 1> length{};  // by match length, with extra bits
  Code end_of_block;
};

constexpr Tables makeTables() {
  Tables t;
  for (int s = 0; s < 256; ++s) t.literal[s] = fixedSymbol(s);
  for (int i = 0; i < 29; ++i) {
    // Code 284 ends at 257: 258 has its own code, 285.
    const int last = i + 1 < 29 ? kLengthBase[i + 1] - 1 : 258;
    for (int len = kLengthBase[i]; len <= last; ++len) {
      const Code c = fixedSymbol(257 + i);
      t.length[len] = {c.bits | (static_cast<std::uint32_t>(len - kLengthBase[i]) << c.length),
                       c.length + kLengthExtra[i]};
    }
  }
  t.end_of_block = fixedSymbol(256);
  return t;
}

constexpr Tables kTables = makeTables();

// The distance code of `d` with its extra bits (distance codes are 5 fixed bits).
Code distanceCode(std::size_t d) {
  const auto it = std::upper_bound(kDistanceBase.begin(), kDistanceBase.end(), d) - 1;
  const auto i = static_cast<std::size_t>(it - kDistanceBase.begin());
  return {reversed(static_cast<std::uint32_t>(i), 5) |
              (static_cast<std::uint32_t>(d - kDistanceBase[i]) << 5),
          5 + kDistanceExtra[i]};
}

class BitWriter {
 public:
  explicit BitWriter(std::vector<unsigned char>& out) : out_(out) {}
  void put(std::uint32_t bits, int count) {
    buffer_ |= static_cast<std::uint64_t>(bits) << used_;
    used_ += count;
    while (used_ >= 8) {
      out_.push_back(static_cast<unsigned char>(buffer_));
      buffer_ >>= 8;
      used_ -= 8;
    }
  }
  void flush() {
    if (used_ > 0) out_.push_back(static_cast<unsigned char>(buffer_));
    buffer_ = 0;
    used_ = 0;
  }

 private:
  std::vector<unsigned char>& out_;
  std::uint64_t buffer_ = 0;
  int used_ = 0;
};

// How many bytes from p on equal those `distance` before, at most `limit`.
std::size_t matchLength(const unsigned char* p, std::size_t distance, std::size_t limit) {
  const unsigned char* q = p - distance;
  std::size_t n = 0;
  while (n + 8 <= limit) {
    std::uint64_t a;
    std::uint64_t b;
    std::memcpy(&a, p + n, 8);
    std::memcpy(&b, q + n, 8);
    if (a != b) return n + static_cast<std::size_t>(__builtin_ctzll(a ^ b) / 8);  // little endian
    n += 8;
  }
  while (n < limit && p[n] == q[n]) ++n;
  return n;
}

}  // namespace

void runLengthDeflate(const unsigned char* data, std::size_t begin, std::size_t end,
                      std::size_t pixel_bytes, std::size_t row_bytes, bool final,
                      std::vector<unsigned char>& out) {
  out.reserve(out.size() + (end - begin) + (end - begin) / 8 + 16);
  BitWriter bits(out);
  bits.put(final ? 1 : 0, 1);  // BFINAL
  bits.put(1, 2);              // BTYPE 01: fixed Huffman codes
  const std::size_t distances[2] = {pixel_bytes <= kMaxDistance ? pixel_bytes : 0,
                                    row_bytes <= kMaxDistance ? row_bytes : 0};
  const Code distance_codes[2] = {distanceCode(std::max<std::size_t>(distances[0], 1)),
                                  distanceCode(std::max<std::size_t>(distances[1], 1))};
  for (std::size_t p = begin; p < end;) {
    const std::size_t limit = std::min(kMaxMatch, end - p);
    std::size_t best = 0;
    int which = 0;
    for (int k = 0; k < 2; ++k) {
      const std::size_t d = distances[k];
      if (d == 0 || d > p) continue;
      const std::size_t len = matchLength(data + p, d, limit);
      if (len > best) {
        best = len;
        which = k;
      }
    }
    if (best >= kMinMatch) {
      const Code& length = kTables.length[best];
      bits.put(length.bits, length.length);
      bits.put(distance_codes[which].bits, distance_codes[which].length);
      p += best;
    } else {
      const Code& literal = kTables.literal[data[p]];
      bits.put(literal.bits, literal.length);
      ++p;
    }
  }
  bits.put(kTables.end_of_block.bits, kTables.end_of_block.length);
  if (!final) {
    bits.put(0, 3);  // BFINAL 0, BTYPE 00: stored, empty
    bits.flush();    // to the byte boundary, then LEN 0 and NLEN 0xFFFF
    for (unsigned char b : {0x00, 0x00, 0xFF, 0xFF}) out.push_back(b);
  }
  bits.flush();
}

}  // namespace parksim
