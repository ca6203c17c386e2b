#include "parksim/renders/image/Adler32.h"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace parksim {

namespace {

constexpr std::uint32_t kBase = 65521;
// zlib's NMAX: the most bytes before the sums must be reduced to stay within 32 bits.
constexpr std::size_t kMaxRun = 5552;

#if defined(__SSE2__)
std::uint32_t sumLanes(__m128i v) {
  v = _mm_add_epi32(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(1, 0, 3, 2)));
  v = _mm_add_epi32(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(2, 3, 0, 1)));
  return static_cast<std::uint32_t>(_mm_cvtsi128_si32(v));
}

// 16 bytes at a time: a grows by their sum, b by 16 a plus their sum weighted 16, 15, ..., 1.
// Sums of bytes come from _mm_sad_epu8, weighted sums from _mm_madd_epi16 on bytes widened to
// 16 bits. `chunks` * 16 <= kMaxRun, so no lane overflows.
void addChunks(std::uint32_t& a, std::uint32_t& b, const unsigned char* p, std::size_t chunks) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i w_lo = _mm_setr_epi16(16, 15, 14, 13, 12, 11, 10, 9);
  const __m128i w_hi = _mm_setr_epi16(8, 7, 6, 5, 4, 3, 2, 1);
  __m128i sum = zero;       // bytes so far
  __m128i prefixes = zero;  // before each chunk, the bytes of the chunks before it
  __m128i weighted = zero;
  for (std::size_t k = 0; k < chunks; ++k, p += 16) {
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    prefixes = _mm_add_epi32(prefixes, sum);
    sum = _mm_add_epi32(sum, _mm_sad_epu8(x, zero));
    weighted = _mm_add_epi32(weighted, _mm_madd_epi16(_mm_unpacklo_epi8(x, zero), w_lo));
    weighted = _mm_add_epi32(weighted, _mm_madd_epi16(_mm_unpackhi_epi8(x, zero), w_hi));
  }
  const std::uint64_t bytes = 16 * chunks;
  const std::uint64_t new_b = b + bytes * a + 16ull * sumLanes(prefixes) + sumLanes(weighted);
  a = static_cast<std::uint32_t>((a + static_cast<std::uint64_t>(sumLanes(sum))) % kBase);
  b = static_cast<std::uint32_t>(new_b % kBase);
}
#endif

}  // namespace

std::uint32_t adler32(std::uint32_t adler, const unsigned char* data, std::size_t n) {
  std::uint32_t a = adler & 0xffff;
  std::uint32_t b = adler >> 16;
  while (n > 0) {
    std::size_t run = std::min(n, kMaxRun);
    n -= run;
#if defined(__SSE2__)
    const std::size_t chunks = run / 16;
    addChunks(a, b, data, chunks);
    data += 16 * chunks;
    run -= 16 * chunks;
#endif
    for (; run > 0; --run) {
      a += *data++;
      b += a;
    }
    a %= kBase;
    b %= kBase;
  }
  return (b << 16) | a;
}

}  // namespace parksim
