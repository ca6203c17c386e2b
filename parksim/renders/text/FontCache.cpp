#include "parksim/renders/text/FontCache.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "parksim/core/io/Error.h"

namespace parksim {

FontCache::FontCache(std::vector<unsigned char> ttf) : ttf_(std::move(ttf)) {}

int FontCache::key(float size_px) { return std::max(4, static_cast<int>(std::lround(size_px))); }

const FontAtlas& FontCache::atlas(int font_px) {
  if (ttf_.empty()) throw Error("font: no font to draw text with");
  auto it = atlases_.find(font_px);
  if (it == atlases_.end()) {
    it = atlases_.emplace(font_px, FontAtlas(ttf_, static_cast<float>(font_px))).first;
  }
  return it->second;
}

}  // namespace parksim
