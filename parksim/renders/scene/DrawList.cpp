#include "parksim/renders/scene/DrawList.h"

namespace parksim {

void DrawList::clear() {
  ground.reset();
  mesh.clear();
  mesh_blend.clear();
  lines.clear();
  lines_blend.clear();
  text_boxes.clear();
  glyphs.clear();
}

std::array<PixelRect, 4> DrawList::groundMargins() const {
  if (!ground) return {};
  const PixelRect& r = *ground;
  const int w = width_px;
  const int h = height_px;
  return {{
      {0, 0, w, r.y},                                     // above
      {0, r.y + r.height, w, h - r.y - r.height},         // below
      {0, r.y, r.x, r.height},                            // left
      {r.x + r.width, r.y, w - r.x - r.width, r.height},  // right
  }};
}

std::size_t DrawList::triangleCount() const {
  std::size_t vertices =
      mesh.size() + mesh_blend.size() + lines.size() + lines_blend.size() + text_boxes.size();
  for (const GlyphBatch& b : glyphs) vertices += b.vertices.size();
  return vertices / 3;
}

}  // namespace parksim
