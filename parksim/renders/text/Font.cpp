#include "parksim/renders/text/Font.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include <stb/stb_truetype.h>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

struct CodeRange {
  char32_t first;
  int count;
};
// ASCII, Latin-1 supplement (degree sign, plus-minus, micro), Greek capitals and small letters.
constexpr std::array<CodeRange, 3> kRanges = {{{0x20, 95}, {0xA0, 96}, {0x391, 57}}};

}  // namespace

std::vector<unsigned char> readFontFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw Error(path + ": cannot read font: " + std::strerror(errno) +
                " (the default font comes with the Debian package fonts-dejavu-core)");
  }
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<char32_t> decodeUtf8(std::string_view s) {
  std::vector<char32_t> out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const auto b0 = static_cast<unsigned char>(s[i]);
    int extra = 0;
    char32_t cp = 0;
    if (b0 < 0x80) {
      cp = b0;
    } else if ((b0 & 0xE0) == 0xC0) {
      extra = 1;
      cp = b0 & 0x1F;
    } else if ((b0 & 0xF0) == 0xE0) {
      extra = 2;
      cp = b0 & 0x0F;
    } else if ((b0 & 0xF8) == 0xF0) {
      extra = 3;
      cp = b0 & 0x07;
    } else {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    if (i + static_cast<std::size_t>(extra) >= s.size()) {  // truncated sequence
      out.push_back(0xFFFD);
      break;
    }
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto b = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      if ((b & 0xC0) != 0x80) {
        ok = false;
        break;
      }
      cp = (cp << 6) | (b & 0x3F);
    }
    if (!ok) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    out.push_back(cp);
    i += static_cast<std::size_t>(extra) + 1;
  }
  return out;
}

struct FontAtlas::Impl {
  float pixel_height = 0.0f;
  float ascent = 0.0f;
  float descent = 0.0f;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> bitmap;
  std::array<std::vector<stbtt_packedchar>, kRanges.size()> chars;

  // Range and index of a code point's glyph; '?' when the font lacks it.
  std::pair<std::size_t, int> find(char32_t cp) const {
    for (std::size_t r = 0; r < kRanges.size(); ++r) {
      const auto offset = static_cast<long>(cp) - static_cast<long>(kRanges[r].first);
      if (offset >= 0 && offset < kRanges[r].count) return {r, static_cast<int>(offset)};
    }
    return {0, '?' - 0x20};
  }
};

FontAtlas::FontAtlas(std::span<const unsigned char> ttf, float pixel_height)
    : impl_(std::make_unique<Impl>()) {
  if (!(pixel_height > 0.0f)) throw Error("font: pixel height must be positive");
  const int offset = stbtt_GetFontOffsetForIndex(ttf.data(), 0);
  stbtt_fontinfo info;
  if (ttf.size() < 12 || offset < 0 || !stbtt_InitFont(&info, ttf.data(), offset)) {
    throw Error("font: not a TrueType font");
  }
  int ascent = 0;
  int descent = 0;
  int line_gap = 0;
  stbtt_GetFontVMetrics(&info, &ascent, &descent, &line_gap);
  const float scale = stbtt_ScaleForPixelHeight(&info, pixel_height);
  impl_->pixel_height = pixel_height;
  impl_->ascent = static_cast<float>(ascent) * scale;
  impl_->descent = -static_cast<float>(descent) * scale;

  // Smallest power-of-two square that holds every glyph.
  for (int side = 128; side <= 4096; side *= 2) {
    impl_->bitmap.assign(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
    std::array<stbtt_pack_range, kRanges.size()> ranges{};
    for (std::size_t r = 0; r < kRanges.size(); ++r) {
      impl_->chars[r].assign(static_cast<std::size_t>(kRanges[r].count), stbtt_packedchar{});
      ranges[r].font_size = pixel_height;
      ranges[r].first_unicode_codepoint_in_range = static_cast<int>(kRanges[r].first);
      ranges[r].num_chars = kRanges[r].count;
      ranges[r].chardata_for_range = impl_->chars[r].data();
    }
    stbtt_pack_context pc;
    if (!stbtt_PackBegin(&pc, impl_->bitmap.data(), side, side, 0, 1, nullptr)) break;
    const int ok =
        stbtt_PackFontRanges(&pc, ttf.data(), 0, ranges.data(), static_cast<int>(ranges.size()));
    stbtt_PackEnd(&pc);
    if (ok) {
      impl_->width = side;
      impl_->height = side;
      return;
    }
  }
  throw Error("font: glyphs do not fit a 4096x4096 atlas at this pixel height");
}

FontAtlas::~FontAtlas() = default;
FontAtlas::FontAtlas(FontAtlas&&) noexcept = default;
FontAtlas& FontAtlas::operator=(FontAtlas&&) noexcept = default;

float FontAtlas::pixelHeight() const { return impl_->pixel_height; }
float FontAtlas::ascent() const { return impl_->ascent; }
float FontAtlas::descent() const { return impl_->descent; }
int FontAtlas::atlasWidth() const { return impl_->width; }
int FontAtlas::atlasHeight() const { return impl_->height; }
const std::vector<std::uint8_t>& FontAtlas::bitmap() const { return impl_->bitmap; }

void FontAtlas::layout(std::string_view utf8, float x, float baseline_y,
                       std::vector<GlyphQuad>& out) const {
  // Whole-pixel pen positions keep the glyphs as crisp as they were rasterized.
  float pen_x = std::round(x);
  float pen_y = std::round(baseline_y);
  for (char32_t cp : decodeUtf8(utf8)) {
    const auto [range, index] = impl_->find(cp);
    stbtt_aligned_quad q;
    stbtt_GetPackedQuad(impl_->chars[range].data(), impl_->width, impl_->height, index, &pen_x,
                        &pen_y, &q, 1);
    if (q.x1 > q.x0 && q.y1 > q.y0) {
      out.push_back({q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1});
    }
  }
}

float FontAtlas::advance(std::string_view utf8) const {
  float width = 0.0f;
  for (char32_t cp : decodeUtf8(utf8)) {
    const auto [range, index] = impl_->find(cp);
    width += impl_->chars[range][static_cast<std::size_t>(index)].xadvance;
  }
  return width;
}

}  // namespace parksim
