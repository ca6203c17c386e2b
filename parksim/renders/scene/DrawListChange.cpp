#include "parksim/renders/scene/DrawListChange.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace parksim {

namespace {

PixelRect unite(const PixelRect& a, const PixelRect& b) {
  const int x0 = std::min(a.x, b.x);
  const int y0 = std::min(a.y, b.y);
  const int x1 = std::max(a.x + a.width, b.x + b.width);
  const int y1 = std::max(a.y + a.height, b.y + b.height);
  return {x0, y0, x1 - x0, y1 - y0};
}

long long area(const PixelRect& r) { return static_cast<long long>(r.width) * r.height; }

// Rectangles that overlap or meet are merged: one copy and one draw instead of two, for the few
// pixels of their union that neither covers.
bool touches(const PixelRect& a, const PixelRect& b) {
  return a.x <= b.x + b.width && b.x <= a.x + a.width && a.y <= b.y + b.height &&
         b.y <= a.y + a.height;
}

// Gathers the changed triangles' rectangles, merging as it goes so that the list stays short
// whatever the number of triangles.
class RectSet {
 public:
  RectSet(int width, int height, const DrawListChangeDef& def)
      : width_(width),
        height_(height),
        margin_px_(std::clamp(def.margin_px, 0, 64)),
        max_rects_(std::clamp(def.max_rects, 1, 64)) {}

  // A triangle whose vertices are at these clip-space positions changed.
  void addTriangle(const Eigen::Vector4f (&clip)[3]) {
    float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const Eigen::Vector4f& c : clip) {
      // Behind the camera (or on its plane) a vertex has no place on the image: GL clips the
      // triangle, and where its rest lands is not worth working out.
      if (!(c.w() > 1e-6f) || !c.allFinite()) {
        everything_ = true;
        return;
      }
      const float x = (c.x() / c.w() + 1.0f) * 0.5f * static_cast<float>(width_);
      const float y = (c.y() / c.w() + 1.0f) * 0.5f * static_cast<float>(height_);
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
    const auto m = static_cast<float>(margin_px_);
    const auto w = static_cast<float>(width_);
    const auto h = static_cast<float>(height_);
    if (x1 + m <= 0.0f || y1 + m <= 0.0f || x0 - m >= w || y0 - m >= h) return;  // off the image
    // Clamped before the conversion: far outside the image a float overflows an int.
    const int rx0 = static_cast<int>(std::floor(std::max(0.0f, x0 - m)));
    const int ry0 = static_cast<int>(std::floor(std::max(0.0f, y0 - m)));
    const int rx1 = static_cast<int>(std::ceil(std::min(w, x1 + m)));
    const int ry1 = static_cast<int>(std::ceil(std::min(h, y1 + m)));
    if (rx1 <= rx0 || ry1 <= ry0) return;
    add({rx0, ry0, rx1 - rx0, ry1 - ry0});
  }

  void setEverything() { everything_ = true; }
  bool everything() const { return everything_; }

  std::vector<PixelRect> result() {
    if (everything_) return {{0, 0, width_, height_}};
    mergeTouching();
    while (static_cast<int>(rects_.size()) > max_rects_) mergeCheapestPair();
    return rects_;
  }

 private:
  void add(const PixelRect& r) {
    for (PixelRect& kept : rects_) {
      if (touches(kept, r)) {
        kept = unite(kept, r);
        return;
      }
    }
    // A scattered change would make a long list; beyond a few times the rectangles wanted, the
    // new one joins the rectangle it grows least.
    if (static_cast<int>(rects_.size()) >= 4 * max_rects_) {
      auto best = std::min_element(rects_.begin(), rects_.end(), [&](const auto& a, const auto& b) {
        return area(unite(a, r)) - area(a) < area(unite(b, r)) - area(b);
      });
      *best = unite(*best, r);
      return;
    }
    rects_.push_back(r);
  }

  void mergeTouching() {
    for (bool merged = true; merged;) {
      merged = false;
      for (std::size_t i = 0; i < rects_.size() && !merged; ++i) {
        for (std::size_t j = i + 1; j < rects_.size(); ++j) {
          if (touches(rects_[i], rects_[j])) {
            rects_[i] = unite(rects_[i], rects_[j]);
            rects_.erase(rects_.begin() + static_cast<std::ptrdiff_t>(j));
            merged = true;
            break;
          }
        }
      }
    }
  }

  void mergeCheapestPair() {
    std::size_t bi = 0, bj = 1;
    long long best = -1;
    for (std::size_t i = 0; i < rects_.size(); ++i) {
      for (std::size_t j = i + 1; j < rects_.size(); ++j) {
        const long long growth =
            area(unite(rects_[i], rects_[j])) - area(rects_[i]) - area(rects_[j]);
        if (best < 0 || growth < best) {
          best = growth;
          bi = i;
          bj = j;
        }
      }
    }
    rects_[bi] = unite(rects_[bi], rects_[bj]);
    rects_.erase(rects_.begin() + static_cast<std::ptrdiff_t>(bj));
    mergeTouching();
  }

  int width_;
  int height_;
  int margin_px_;
  int max_rects_;
  bool everything_ = false;
  std::vector<PixelRect> rects_;
};

Eigen::Vector4f clipOf(const MeshVertex& v, const Eigen::Matrix4f& view_proj) {
  return view_proj * Eigen::Vector4f(v.pos[0], v.pos[1], v.pos[2], 1.0f);
}

// The overlay shader flips y, so that rows are read back top first (RendererPrograms).
Eigen::Vector4f clipOf(const OverlayVertex& v, const Eigen::Matrix4f&) {
  return {v.pos[0], -v.pos[1], v.pos[2], v.pos[3]};
}

// Vertices are plain floats and bytes with no padding: equal bytes, equal pixels.
template <class Vertex>
bool sameTriangle(const std::vector<Vertex>& a, std::size_t i, const std::vector<Vertex>& b,
                  std::size_t j) {
  return std::memcmp(&a[3 * i], &b[3 * j], 3 * sizeof(Vertex)) == 0;
}

template <class Vertex>
void addTriangles(const std::vector<Vertex>& v, std::size_t first, std::size_t end,
                  const Eigen::Matrix4f& view_proj, RectSet& rects) {
  for (std::size_t t = first; t < end && !rects.everything(); ++t) {
    const Eigen::Vector4f clip[3] = {clipOf(v[3 * t], view_proj), clipOf(v[3 * t + 1], view_proj),
                                     clipOf(v[3 * t + 2], view_proj)};
    rects.addTriangle(clip);
  }
}

// One batch: walks both lists, keeping the triangles they share in order and handing the others
// to `rects`. Where they part, it looks a few triangles ahead in each for the other's next one:
// a triangle left out (the path's start dropped) or put in (the path grew) keeps the rest
// matched. Anything matched this way is a common subsequence, so the result is right whatever
// the window; the window only decides how much is found in common.
template <class Vertex>
void diffBatch(const std::vector<Vertex>& before, const std::vector<Vertex>& after,
               const Eigen::Matrix4f& view_proj, int lookahead, RectSet& rects) {
  const std::size_t nb = before.size() / 3;
  const std::size_t na = after.size() / 3;
  const auto window = static_cast<std::size_t>(std::clamp(lookahead, 0, 1024));
  std::size_t i = 0, j = 0;
  while (i < nb && j < na && !rects.everything()) {
    if (sameTriangle(before, i, after, j)) {
      ++i;
      ++j;
      continue;
    }
    std::size_t dropped = 0, added = 0;  // 0: not found within the window
    const std::size_t reach = std::min(window, std::max(nb - i, na - j));
    for (std::size_t k = 1; k <= reach && (dropped == 0 || added == 0); ++k) {
      if (dropped == 0 && i + k < nb && sameTriangle(before, i + k, after, j)) dropped = k;
      if (added == 0 && j + k < na && sameTriangle(before, i, after, j + k)) added = k;
    }
    if (dropped != 0 && (added == 0 || dropped <= added)) {
      addTriangles(before, i, i + dropped, view_proj, rects);
      i += dropped;
    } else if (added != 0) {
      addTriangles(after, j, j + added, view_proj, rects);
      j += added;
    } else {
      addTriangles(before, i, i + 1, view_proj, rects);
      addTriangles(after, j, j + 1, view_proj, rects);
      ++i;
      ++j;
    }
  }
  addTriangles(before, i, nb, view_proj, rects);
  addTriangles(after, j, na, view_proj, rects);
}

bool sameUniforms(const DrawList& a, const DrawList& b) {
  return a.width_px == b.width_px && a.height_px == b.height_px && a.lit == b.lit &&
         a.view_proj == b.view_proj && a.light == b.light && a.ambient == b.ambient &&
         a.up_factor == b.up_factor && a.clear_color == b.clear_color &&
         a.background == b.background && a.ground == b.ground;
}

}  // namespace

std::vector<PixelRect> changedRects(const DrawList& before, const DrawList& after,
                                    const DrawListChangeDef& def) {
  RectSet rects(after.width_px, after.height_px, def);
  if (after.width_px <= 0 || after.height_px <= 0) return {};
  if (!sameUniforms(before, after)) {
    rects.setEverything();
    return rects.result();
  }
  const Eigen::Matrix4f& vp = after.view_proj;
  diffBatch(before.mesh, after.mesh, vp, def.lookahead, rects);
  diffBatch(before.mesh_blend, after.mesh_blend, vp, def.lookahead, rects);
  diffBatch(before.lines, after.lines, vp, def.lookahead, rects);
  diffBatch(before.lines_blend, after.lines_blend, vp, def.lookahead, rects);
  diffBatch(before.text_boxes, after.text_boxes, vp, def.lookahead, rects);
  // Glyph batches come by font size, ascending: those of one size are compared, a size only
  // one list has changed entirely.
  const std::vector<OverlayVertex> none;
  std::size_t i = 0, j = 0;
  while (i < before.glyphs.size() || j < after.glyphs.size()) {
    const GlyphBatch* b = i < before.glyphs.size() ? &before.glyphs[i] : nullptr;
    const GlyphBatch* a = j < after.glyphs.size() ? &after.glyphs[j] : nullptr;
    if (b && a && b->font_px == a->font_px) {
      diffBatch(b->vertices, a->vertices, vp, def.lookahead, rects);
      ++i;
      ++j;
    } else if (b && (!a || b->font_px < a->font_px)) {
      diffBatch(b->vertices, none, vp, def.lookahead, rects);
      ++i;
    } else {
      diffBatch(none, a->vertices, vp, def.lookahead, rects);
      ++j;
    }
  }
  return rects.result();
}

}  // namespace parksim
