#pragma once
// Text with stb_truetype: glyphs of a TrueType font (DejaVu Sans Mono from fonts-dejavu-core by
// default, found through fontconfig: FontLookup.h) packed into one coverage bitmap per pixel size,
// and laid out as textured quads. Pure CPU work; the renderer uploads the bitmap once and draws the
// quads.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace parksim {

/// Reads a whole font file. Throws Error naming the file and the package that ships the default.
std::vector<unsigned char> readFontFile(const std::string& path);

/// One glyph on screen: pixel rectangle (y down) and its texture coordinates in the atlas.
struct GlyphQuad {
  float x0, y0, x1, y1;
  float s0, t0, s1, t1;
};

/// Glyphs of ASCII, Latin-1 (the degree sign) and Greek (theta) at one pixel height. Other code
/// points are drawn as '?'.
class FontAtlas {
 public:
  /// Packs the glyphs of `ttf` (a TrueType file's bytes, which must outlive the call only) at
  /// `pixel_height` (> 0). Throws Error when the data is not a font.
  FontAtlas(std::span<const unsigned char> ttf, float pixel_height);
  ~FontAtlas();
  FontAtlas(FontAtlas&&) noexcept;
  FontAtlas& operator=(FontAtlas&&) noexcept;

  float pixelHeight() const;
  /// Distance from the baseline up to the top of the tallest glyphs, pixels.
  float ascent() const;
  /// Distance from the baseline down to the bottom of descenders, pixels (positive).
  float descent() const;
  int atlasWidth() const;
  int atlasHeight() const;
  /// atlasWidth x atlasHeight coverage bytes, rows top to bottom.
  const std::vector<std::uint8_t>& bitmap() const;

  /// Quads of `utf8` with the pen starting at (x, baseline_y), pixels, y down. Appends to `out`.
  void layout(std::string_view utf8, float x, float baseline_y, std::vector<GlyphQuad>& out) const;
  /// Horizontal advance of `utf8`, pixels.
  float advance(std::string_view utf8) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Decodes UTF-8 into code points; malformed bytes become U+FFFD.
std::vector<char32_t> decodeUtf8(std::string_view utf8);

}  // namespace parksim
