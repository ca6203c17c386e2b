#pragma once
// One font's glyph atlases by pixel size, packed on first use and kept: a renderer draws the
// same few sizes in every image. Pure CPU work (the renderer uploads each atlas once as a
// texture).

#include <map>
#include <vector>

#include "parksim/renders/text/Font.h"

namespace parksim {

class FontCache {
 public:
  /// No font: text is not drawn.
  FontCache() = default;
  /// `ttf`: a TrueType file's bytes (readFontFile); empty: no font.
  explicit FontCache(std::vector<unsigned char> ttf);

  /// Whether there is a font to draw text with.
  bool hasFont() const { return !ttf_.empty(); }

  /// The atlas size text of `size_px` pixels is drawn with: rounded, at least 4 pixels.
  static int key(float size_px);

  /// The atlas of `font_px` pixels (a key()). Throws Error when there is no font or the data is
  /// not a font.
  const FontAtlas& atlas(int font_px);

 private:
  std::vector<unsigned char> ttf_;
  std::map<int, FontAtlas> atlases_;
};

}  // namespace parksim
