#include "parksim/renders/scene/SceneTessellator.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace parksim {

namespace {

void setColor(std::uint8_t* dst, const Rgba8& c) {
  dst[0] = c.r;
  dst[1] = c.g;
  dst[2] = c.b;
  dst[3] = c.a;
}

// The glyph batch of `font_px`, kept in ascending order of size.
std::vector<OverlayVertex>& glyphBatch(std::vector<GlyphBatch>& batches, int font_px) {
  auto it = std::lower_bound(batches.begin(), batches.end(), font_px,
                             [](const GlyphBatch& b, int px) { return b.font_px < px; });
  if (it == batches.end() || it->font_px != font_px) it = batches.insert(it, {font_px, {}});
  return it->vertices;
}

}  // namespace

std::optional<PixelRect> groundRectangle(const Scene& scene, const Camera& cam) {
  if (cam.perspective || scene.polygons.empty()) return std::nullopt;
  const ScenePolygon& p = scene.polygons.front();
  if (p.color.a != 255 || p.points.size() != 4) return std::nullopt;
  double x0 = p.points[0].x(), x1 = x0, y0 = p.points[0].y(), y1 = y0;
  for (const Eigen::Vector2d& q : p.points) {
    x0 = std::min(x0, q.x());
    x1 = std::max(x1, q.x());
    y0 = std::min(y0, q.y());
    y1 = std::max(y1, q.y());
  }
  // A rectangle: every vertex a corner, every edge along one axis (so no corner repeats and the
  // outline does not cross itself).
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector2d& q = p.points[i];
    const Eigen::Vector2d& r = p.points[(i + 1) % 4];
    if ((q.x() != x0 && q.x() != x1) || (q.y() != y0 && q.y() != y1)) return std::nullopt;
    if ((q.x() == r.x()) == (q.y() == r.y())) return std::nullopt;
  }
  const auto a = cam.project({x0, y1, p.z_m});  // top-left on screen
  const auto b = cam.project({x1, y0, p.z_m});  // bottom-right
  if (!a || !b) return std::nullopt;
  // Pixel i is covered when its centre i + 0.5 lies inside.
  auto first = [](double v) { return static_cast<int>(std::ceil(v - 0.5)); };
  const int i0 = std::max(first(a->x()), 0);
  const int i1 = std::min(first(b->x()), cam.width_px);
  const int j0 = std::max(first(a->y()), 0);
  const int j1 = std::min(first(b->y()), cam.height_px);
  if (i1 <= i0 || j1 <= j0) return PixelRect{0, 0, 0, 0};
  return PixelRect{i0, j0, i1 - i0, j1 - j0};
}

void SceneTessellator::tessellate(const Scene& scene, const Camera& cam, const TessellationDef& def,
                                  FontCache& fonts, DrawList& out) {
  out.clear();
  out_ = &out;
  samples_ = std::max(1, def.samples);
  out.width_px = cam.width_px;
  out.height_px = cam.height_px;
  out.background = scene.background;
  // A top view's first polygon, when it is an opaque axis-aligned rectangle (the lot's
  // surface), is nothing but a coloured rectangle under everything else: a scissored clear
  // fills it several times faster than llvmpipe shades it. The pixel range follows the
  // rasterizer's rule (pixel centres inside), so the result is the same.
  out.ground = def.ground_clear ? groundRectangle(scene, cam) : std::nullopt;
  out.clear_color = out.ground ? scene.polygons.front().color : scene.background;
  for (std::size_t i = out.ground ? 1 : 0; i < scene.polygons.size(); ++i) {
    const ScenePolygon& p = scene.polygons[i];
    addPolygon(p.points, p.z_m, p.color);
  }
  for (const SceneBox& b : scene.boxes) addBox(b);
  for (const ScenePrism& p : scene.prisms) addPrism(p);
  const Eigen::Matrix4d vp = cam.viewProjection();
  if (samples_ == 1 && !cam.perspective) addEdgeOutlines(scene, vp);
  for (const ScenePolyline& l : scene.lines) addPolyline(l, vp);
  for (const SceneArrow& a : scene.arrows) addArrow(a, vp);
  if (fonts.hasFont()) {
    for (const SceneText& t : scene.texts) addText(t, cam, fonts);
  }
  setUniforms(cam, def);
  out_ = nullptr;
}

void SceneTessellator::setUniforms(const Camera& cam, const TessellationDef& def) {
  // Flipping y in clip space makes row 0 of the framebuffer the image's top row.
  Eigen::Matrix4f flip = Eigen::Matrix4f::Identity();
  flip(1, 1) = -1.0f;
  out_->view_proj = flip * cam.viewProjection().cast<float>();
  out_->lit = cam.perspective;
  const Eigen::Vector3d light = def.light_direction.normalized();
  const double ambient = std::clamp(def.ambient, 0.0, 1.0);
  const double up = ambient + (1.0 - ambient) * std::max(light.z(), 0.0);
  out_->light = {static_cast<float>(light.x()), static_cast<float>(light.y()),
                 static_cast<float>(light.z())};
  out_->ambient = static_cast<float>(ambient);
  out_->up_factor = static_cast<float>(std::max(up, 1e-3));
}

void SceneTessellator::addTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c, const Eigen::Vector3d& n,
                                   const Rgba8& color) {
  std::vector<MeshVertex>& mesh = color.a == 255 ? out_->mesh : out_->mesh_blend;
  for (const Eigen::Vector3d* p : {&a, &b, &c}) {
    MeshVertex v;
    v.pos[0] = static_cast<float>(p->x());
    v.pos[1] = static_cast<float>(p->y());
    v.pos[2] = static_cast<float>(p->z());
    v.normal[0] = static_cast<float>(n.x());
    v.normal[1] = static_cast<float>(n.y());
    v.normal[2] = static_cast<float>(n.z());
    setColor(v.color, color);
    mesh.push_back(v);
  }
}

void SceneTessellator::addBox(const SceneBox& box) {
  const auto corners = box.footprint.corners();
  const double z0 = box.z_min_m;
  const double z1 = box.z_min_m + box.height_m;
  auto lo = [&](int i) { return Eigen::Vector3d(corners[i].x(), corners[i].y(), z0); };
  auto hi = [&](int i) { return Eigen::Vector3d(corners[i].x(), corners[i].y(), z1); };
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  addTriangle(hi(0), hi(1), hi(2), up, box.color);
  addTriangle(hi(0), hi(2), hi(3), up, box.color);
  // No bottom face: no camera looks at a box from below the ground.
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const Eigen::Vector2d edge = corners[j] - corners[i];
    const Eigen::Vector3d n = Eigen::Vector3d(edge.y(), -edge.x(), 0.0).normalized();
    addTriangle(lo(i), lo(j), hi(j), n, box.color);
    addTriangle(lo(i), hi(j), hi(i), n, box.color);
  }
}

void SceneTessellator::addPrism(const ScenePrism& prism) {
  const std::vector<Eigen::Vector2d>& p = prism.footprint;
  const std::size_t n = p.size();
  if (n < 3) return;
  const double z0 = prism.z_min_m;
  const double z1 = prism.z_min_m + prism.height_m;
  addPolygon(p, z1, prism.color);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const Eigen::Vector2d edge = p[j] - p[i];
    const Eigen::Vector3d normal = Eigen::Vector3d(edge.y(), -edge.x(), 0.0).normalized();
    const Eigen::Vector3d a(p[i].x(), p[i].y(), z0);
    const Eigen::Vector3d b(p[j].x(), p[j].y(), z0);
    const Eigen::Vector3d c(p[j].x(), p[j].y(), z1);
    const Eigen::Vector3d d(p[i].x(), p[i].y(), z1);
    addTriangle(a, b, c, normal, prism.color);
    addTriangle(a, c, d, normal, prism.color);
  }
}

void SceneTessellator::addPolygon(const std::vector<Eigen::Vector2d>& pts, double z,
                                  const Rgba8& color) {
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    addTriangle({pts[0].x(), pts[0].y(), z}, {pts[i].x(), pts[i].y(), z},
                {pts[i + 1].x(), pts[i + 1].y(), z}, Eigen::Vector3d::UnitZ(), color);
  }
}

void SceneTessellator::addSegment(Eigen::Vector4d c0, Eigen::Vector4d c1, float width_px,
                                  const Rgba8& color, bool edge_smoothing) {
  // Clip against the near plane (z >= -w) before dividing, so a perspective view can hold
  // paths that pass behind the camera.
  const double d0 = c0.z() + c0.w();
  const double d1 = c1.z() + c1.w();
  if (d0 < 0.0 && d1 < 0.0) return;
  if (d0 < 0.0) c0 += (c1 - c0) * (d0 / (d0 - d1));
  if (d1 < 0.0) c1 += (c0 - c1) * (d1 / (d1 - d0));
  if (c0.w() <= 1e-12 || c1.w() <= 1e-12) return;
  const Eigen::Vector2d half(0.5 * out_->width_px, 0.5 * out_->height_px);  // NDC to pixels
  const Eigen::Vector2d p0 = c0.head<2>() / c0.w();
  const Eigen::Vector2d p1 = c1.head<2>() / c1.w();
  Eigen::Vector2d dir = (p1 - p0).cwiseProduct(half);
  const double len = dir.norm();
  dir = len > 1e-9 ? Eigen::Vector2d(dir / len) : Eigen::Vector2d(1.0, 0.0);
  // An axis-aligned segment has no staircase to smooth: it is drawn solid, without blending,
  // and an edge-smoothing outline along it is not needed at all.
  const bool axis_aligned = std::abs(dir.x()) < 1e-9 || std::abs(dir.y()) < 1e-9;
  if (axis_aligned && edge_smoothing) return;
  // Square caps: consecutive segments overlap at their joints, which leaves no notch at a bend.
  // Without multisampling the ribbon grows by half a pixel a side for the shader's fade-out.
  const bool feather = samples_ == 1 && !axis_aligned;
  const double hw = 0.5 * width_px + (feather ? 0.5 : 0.0);
  const Eigen::Vector2d side = Eigen::Vector2d(-dir.y(), dir.x()) * hw;
  const Eigen::Vector2d cap = dir * hw;
  auto vertex = [&](const Eigen::Vector2d& p, const Eigen::Vector4d& c, const Eigen::Vector2d& off,
                    double across) {
    const Eigen::Vector2d q = p + off.cwiseQuotient(half);
    OverlayVertex v;
    v.pos[0] = static_cast<float>(q.x() * c.w());
    v.pos[1] = static_cast<float>(q.y() * c.w());
    v.pos[2] = static_cast<float>(c.z());
    v.pos[3] = static_cast<float>(c.w());
    v.uv[0] = static_cast<float>(across);
    v.uv[1] = feather ? 0.5f * width_px : kSolidHalfWidth;
    setColor(v.color, color);
    return v;
  };
  const OverlayVertex a = vertex(p0, c0, -cap + side, hw);
  const OverlayVertex b = vertex(p0, c0, -cap - side, -hw);
  const OverlayVertex c = vertex(p1, c1, cap + side, hw);
  const OverlayVertex d = vertex(p1, c1, cap - side, -hw);
  std::vector<OverlayVertex>& out = color.a == 255 && !feather ? out_->lines : out_->lines_blend;
  out.insert(out.end(), {a, b, c, b, d, c});
}

void SceneTessellator::addPolyline(const ScenePolyline& line, const Eigen::Matrix4d& vp,
                                   bool edge_smoothing) {
  const std::size_t n = line.points.size();
  if (n < 2) return;
  // Points closer on screen than one and a half line widths to the last one kept add triangles
  // (which llvmpipe pays for one by one) but hardly a pixel (a 4 px chord of a 20 px radius
  // strays 0.1 px): dense paths are thinned here. Points behind a perspective camera are always
  // kept; the segment clipping handles them.
  const double min_px = std::max(2.0, 1.5 * line.width_px);
  const Eigen::Vector2d half(0.5 * out_->width_px, 0.5 * out_->height_px);
  clip_.clear();
  Eigen::Vector2d last_px(0.0, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector4d c = vp * line.points[i].homogeneous();
    if (c.w() > 1e-12 && i > 0 && i + 1 < n) {
      const Eigen::Vector2d px = (c.head<2>() / c.w()).cwiseProduct(half);
      if ((px - last_px).norm() < min_px) continue;
      last_px = px;
    } else if (c.w() > 1e-12) {
      last_px = (c.head<2>() / c.w()).cwiseProduct(half);
    }
    clip_.push_back(c);
  }
  for (std::size_t i = 0; i + 1 < clip_.size(); ++i) {
    addSegment(clip_[i], clip_[i + 1], line.width_px, line.color, edge_smoothing);
  }
  if (line.closed && clip_.size() > 2) {
    addSegment(clip_.back(), clip_.front(), line.width_px, line.color, edge_smoothing);
  }
}

void SceneTessellator::addEdgeOutlines(const Scene& scene, const Eigen::Matrix4d& vp) {
  // Without multisampling, a top view smooths the edges of what it sees, the polygons and the
  // boxes' top faces, with a fading one-pixel outline in their own colour (the lines'
  // anti-aliasing). The outline sits on the face, so the depth test keeps it under anything
  // higher.
  // edge_ keeps its points' buffer from frame to frame: only its contents change.
  edge_.width_px = 1.0f;
  edge_.closed = true;
  const auto outline = [&](Rgba8 color, const auto& corners, double z_m) {
    if (color.a != 255) return;
    edge_.color = color;
    edge_.points.clear();
    for (const Eigen::Vector2d& q : corners) edge_.points.emplace_back(q.x(), q.y(), z_m);
    addPolyline(edge_, vp, true);
  };
  for (const ScenePolygon& p : scene.polygons) outline(p.color, p.points, p.z_m);
  for (const SceneBox& b : scene.boxes) {
    outline(b.color, b.footprint.corners(), b.z_min_m + b.height_m);
  }
  for (const ScenePrism& p : scene.prisms) {
    outline(p.color, p.footprint, p.z_min_m + p.height_m);
  }
}

void SceneTessellator::addArrow(const SceneArrow& a, const Eigen::Matrix4d& vp) {
  const Eigen::Vector2d dir(std::cos(a.pose.theta), std::sin(a.pose.theta));
  const Eigen::Vector2d tail(a.pose.x, a.pose.y);
  const Eigen::Vector2d tip = tail + dir * a.length_m;
  const double head = std::min(a.head_m, a.length_m);
  const Eigen::Vector2d base = tip - dir * head;
  const Eigen::Vector2d side = Eigen::Vector2d(-dir.y(), dir.x()) * (0.5 * head);
  addSegment(vp * Eigen::Vector4d(tail.x(), tail.y(), a.z_m, 1.0),
             vp * Eigen::Vector4d(base.x(), base.y(), a.z_m, 1.0), a.width_px, a.color);
  addPolygon({tip, base + side, base - side}, a.z_m, a.color);
}

void SceneTessellator::addScreenQuad(float x0, float y0, float x1, float y1, const float uv[4],
                                     const Rgba8& c, std::vector<OverlayVertex>& out) const {
  const auto width = static_cast<float>(out_->width_px);
  const auto height = static_cast<float>(out_->height_px);
  auto vertex = [&](float x, float y, float u, float v) {
    OverlayVertex o;
    o.pos[0] = 2.0f * x / width - 1.0f;
    o.pos[1] = 1.0f - 2.0f * y / height;
    o.pos[2] = 0.0f;
    o.pos[3] = 1.0f;
    o.uv[0] = u;
    o.uv[1] = v;
    setColor(o.color, c);
    return o;
  };
  const OverlayVertex a = vertex(x0, y0, uv[0], uv[1]);
  const OverlayVertex b = vertex(x1, y0, uv[2], uv[1]);
  const OverlayVertex d = vertex(x0, y1, uv[0], uv[3]);
  const OverlayVertex e = vertex(x1, y1, uv[2], uv[3]);
  out.insert(out.end(), {a, b, d, b, e, d});
}

void SceneTessellator::addText(const SceneText& t, const Camera& cam, FontCache& fonts) {
  if (t.text.empty()) return;
  const int font_px = FontCache::key(t.size_px);
  const FontAtlas& atlas = fonts.atlas(font_px);
  Eigen::Vector2d anchor = t.screen_px;
  if (t.world) {
    const auto p = cam.project(*t.world);
    if (!p) return;
    anchor = *p;
  }
  const float w = atlas.advance(t.text);
  const float asc = atlas.ascent();
  const float desc = atlas.descent();
  float x = static_cast<float>(anchor.x());
  if (t.h_align == HAlign::kCenter) x -= 0.5f * w;
  if (t.h_align == HAlign::kRight) x -= w;
  float top = static_cast<float>(anchor.y());
  if (t.v_align == VAlign::kMiddle) top -= 0.5f * (asc + desc);
  if (t.v_align == VAlign::kBottom) top -= asc + desc;
  std::vector<OverlayVertex>& out = glyphBatch(out_->glyphs, font_px);
  if (t.background.a > 0) {
    const float pad = 0.25f * atlas.pixelHeight();
    const float solid[4] = {0.0f, kSolidHalfWidth, 0.0f, kSolidHalfWidth};
    addScreenQuad(x - pad, top - pad, x + w + pad, top + asc + desc + pad, solid, t.background,
                  out_->text_boxes);
  }
  glyphs_.clear();
  atlas.layout(t.text, x, top + asc, glyphs_);
  for (const GlyphQuad& g : glyphs_) {
    const float uv[4] = {g.s0, g.t0, g.s1, g.t1};
    addScreenQuad(g.x0, g.y0, g.x1, g.y1, uv, t.color, out);
  }
}

}  // namespace parksim
