#include "parksim/renders/Renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Geometry>

#include "parksim/core/Error.h"
#include "parksim/renders/Font.h"
#include "parksim/renders/GlFunctions.h"
#include "parksim/renders/RendererPrograms.h"

namespace parksim {

namespace {

struct MeshVertex {
  float pos[3];
  float normal[3];
  std::uint8_t color[4];
};

// Lines and text: positions already in clip space, so lines keep a width in pixels in every view.
struct OverlayVertex {
  float pos[4];
  float uv[2];  // atlas coordinates; negative: solid colour
  std::uint8_t color[4];
};

// Half width given to solid areas drawn by the line shader: never fades.
constexpr float kSolidHalfWidth = 1e6f;

void setColor(std::uint8_t* dst, const Rgba8& c) {
  dst[0] = c.r;
  dst[1] = c.g;
  dst[2] = c.b;
  dst[3] = c.a;
}

// The pixel rectangle {x, y, width, height} (image rows from the top) that a top view's first
// polygon covers, when that polygon is an opaque axis-aligned rectangle; unset otherwise.
std::optional<std::array<int, 4>> groundRectangle(const Scene& scene, const Camera& cam) {
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
  if (i1 <= i0 || j1 <= j0) return std::array<int, 4>{0, 0, 0, 0};
  return std::array<int, 4>{i0, j0, i1 - i0, j1 - j0};
}

// The context is current on the calling thread while the guard lives and released after, so a
// renderer may move between threads (one at a time): EGL refuses to make a context current while
// it is still current on another thread. Releasing costs nothing measurable next to a frame.
class CurrentContext {
 public:
  explicit CurrentContext(OffscreenContext& context) : context_(context) {
    if (!context_.isCurrent()) context_.makeCurrent();
  }
  ~CurrentContext() { context_.releaseCurrent(); }
  CurrentContext(const CurrentContext&) = delete;
  CurrentContext& operator=(const CurrentContext&) = delete;

 private:
  OffscreenContext& context_;
};

}  // namespace

struct Renderer::Impl {
  RenderDef def;
  std::unique_ptr<OffscreenContext> context;
  const GlFunctions* gl = nullptr;  // the context's entry points
  std::vector<unsigned char> font_data;
  std::map<int, std::pair<FontAtlas, GLuint>> fonts;  // by pixel height

  int width = 0;
  int height = 0;
  int samples = 1;
  GLint max_samples = 1;
  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0;
  GLuint resolve_fbo = 0, resolve_color = 0, resolve_depth = 0;
  RendererPrograms programs;
  GLuint mesh_vao = 0, mesh_vbo = 0, overlay_vao = 0, overlay_vbo = 0;

  // Scratch, kept between frames so steady-state drawing does not allocate.
  // Opaque and translucent geometry go to separate batches: blending makes llvmpipe read the
  // framebuffer back for every fragment, so only what needs it pays for it.
  std::vector<MeshVertex> mesh;
  std::vector<MeshVertex> mesh_blend;
  std::vector<OverlayVertex> lines;
  std::vector<OverlayVertex> lines_blend;
  std::vector<OverlayVertex> text;  // boxes behind text
  std::vector<GlyphQuad> glyphs;
  std::vector<Eigen::Vector4d> clip;
  std::vector<std::uint8_t> rgba;  // read-back buffer

  void init();
  void allocateFramebuffers();
  void releaseFramebuffers();
  void ensureCurrent() {
    if (!context->isCurrent()) context->makeCurrent();
  }
  std::pair<FontAtlas, GLuint>* font(float size_px);

  void addTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& n, const Rgba8& color);
  void addBox(const SceneBox& box);
  void addPrism(const ScenePrism& prism);
  void addPolygon(const std::vector<Eigen::Vector2d>& pts, double z, const Rgba8& color);
  void addSegment(Eigen::Vector4d c0, Eigen::Vector4d c1, float width_px, const Rgba8& color,
                  bool edge_smoothing = false);
  void addPolyline(const ScenePolyline& line, const Eigen::Matrix4d& vp,
                   bool edge_smoothing = false);
  void addScreenQuad(float x0, float y0, float x1, float y1, const float uv[4], const Rgba8& c,
                     std::vector<OverlayVertex>& out) const;
  void addText(const SceneText& text, const Camera& cam,
               std::map<int, std::vector<OverlayVertex>>&);

  void draw(const Scene& scene, const Camera& cam);
};

void Renderer::Impl::init() {
  const char* version = reinterpret_cast<const char*>(gl->GetString(GL_VERSION));
  if (version == nullptr) throw Error("renderer: the GL context does not answer");
  gl->GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  programs.create(*gl);

  gl->GenVertexArrays(1, &mesh_vao);
  gl->GenBuffers(1, &mesh_vbo);
  gl->BindVertexArray(mesh_vao);
  gl->BindBuffer(GL_ARRAY_BUFFER, mesh_vbo);
  const auto mesh_stride = static_cast<GLsizei>(sizeof(MeshVertex));
  gl->EnableVertexAttribArray(0);
  gl->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, mesh_stride,
                          reinterpret_cast<void*>(offsetof(MeshVertex, pos)));
  gl->EnableVertexAttribArray(1);
  gl->VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, mesh_stride,
                          reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
  gl->EnableVertexAttribArray(2);
  gl->VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, mesh_stride,
                          reinterpret_cast<void*>(offsetof(MeshVertex, color)));

  gl->GenVertexArrays(1, &overlay_vao);
  gl->GenBuffers(1, &overlay_vbo);
  gl->BindVertexArray(overlay_vao);
  gl->BindBuffer(GL_ARRAY_BUFFER, overlay_vbo);
  const auto overlay_stride = static_cast<GLsizei>(sizeof(OverlayVertex));
  gl->EnableVertexAttribArray(0);
  gl->VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, overlay_stride,
                          reinterpret_cast<void*>(offsetof(OverlayVertex, pos)));
  gl->EnableVertexAttribArray(1);
  gl->VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, overlay_stride,
                          reinterpret_cast<void*>(offsetof(OverlayVertex, uv)));
  gl->EnableVertexAttribArray(2);
  gl->VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, overlay_stride,
                          reinterpret_cast<void*>(offsetof(OverlayVertex, color)));
  gl->BindVertexArray(0);

  gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
  checkGl(*gl, "setup");
}

void Renderer::Impl::releaseFramebuffers() {
  const GLuint fbos[] = {msaa_fbo, resolve_fbo};
  const GLuint rbs[] = {msaa_color, msaa_depth, resolve_color, resolve_depth};
  gl->DeleteFramebuffers(2, fbos);
  gl->DeleteRenderbuffers(4, rbs);
  msaa_fbo = msaa_color = msaa_depth = resolve_fbo = resolve_color = resolve_depth = 0;
}

void Renderer::Impl::allocateFramebuffers() {
  releaseFramebuffers();
  auto storage = [&](GLuint& rb, GLenum format, int n) {
    gl->GenRenderbuffers(1, &rb);
    gl->BindRenderbuffer(GL_RENDERBUFFER, rb);
    if (n > 1) {
      gl->RenderbufferStorageMultisample(GL_RENDERBUFFER, n, format, width, height);
    } else {
      gl->RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
  };
  auto complete = [this](const char* which) {
    if (gl->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw Error(std::string("renderer: ") + which + " framebuffer is incomplete");
    }
  };
  samples = std::clamp(def.msaa_samples, 1, std::max(1, static_cast<int>(max_samples)));
  gl->GenFramebuffers(1, &resolve_fbo);
  gl->BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo);
  storage(resolve_color, GL_RGBA8, 1);
  gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color);
  if (samples == 1) {
    storage(resolve_depth, GL_DEPTH_COMPONENT24, 1);
    gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                resolve_depth);
  }
  complete("resolve");
  if (samples > 1) {
    gl->GenFramebuffers(1, &msaa_fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
    storage(msaa_color, GL_RGBA8, samples);
    gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color);
    storage(msaa_depth, GL_DEPTH_COMPONENT24, samples);
    gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth);
    complete("multisample");
  }
  checkGl(*gl, "framebuffer allocation");
}

std::pair<FontAtlas, GLuint>* Renderer::Impl::font(float size_px) {
  if (font_data.empty()) return nullptr;
  const int key = std::max(4, static_cast<int>(std::lround(size_px)));
  auto it = fonts.find(key);
  if (it == fonts.end()) {
    FontAtlas atlas(font_data, static_cast<float>(key));
    GLuint tex = 0;
    gl->GenTextures(1, &tex);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.atlasWidth(), atlas.atlasHeight(), 0, GL_RED,
                   GL_UNSIGNED_BYTE, atlas.bitmap().data());
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    it = fonts.emplace(key, std::make_pair(std::move(atlas), tex)).first;
  }
  return &it->second;
}

void Renderer::Impl::addTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& c, const Eigen::Vector3d& n,
                                 const Rgba8& color) {
  for (const Eigen::Vector3d* p : {&a, &b, &c}) {
    MeshVertex v;
    v.pos[0] = static_cast<float>(p->x());
    v.pos[1] = static_cast<float>(p->y());
    v.pos[2] = static_cast<float>(p->z());
    v.normal[0] = static_cast<float>(n.x());
    v.normal[1] = static_cast<float>(n.y());
    v.normal[2] = static_cast<float>(n.z());
    setColor(v.color, color);
    (color.a == 255 ? mesh : mesh_blend).push_back(v);
  }
}

void Renderer::Impl::addBox(const SceneBox& box) {
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

void Renderer::Impl::addPrism(const ScenePrism& prism) {
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

void Renderer::Impl::addPolygon(const std::vector<Eigen::Vector2d>& pts, double z,
                                const Rgba8& color) {
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    addTriangle({pts[0].x(), pts[0].y(), z}, {pts[i].x(), pts[i].y(), z},
                {pts[i + 1].x(), pts[i + 1].y(), z}, Eigen::Vector3d::UnitZ(), color);
  }
}

void Renderer::Impl::addSegment(Eigen::Vector4d c0, Eigen::Vector4d c1, float width_px,
                                const Rgba8& color, bool edge_smoothing) {
  // Clip against the near plane (z >= -w) before dividing, so a perspective view can hold
  // paths that pass behind the camera.
  const double d0 = c0.z() + c0.w();
  const double d1 = c1.z() + c1.w();
  if (d0 < 0.0 && d1 < 0.0) return;
  if (d0 < 0.0) c0 += (c1 - c0) * (d0 / (d0 - d1));
  if (d1 < 0.0) c1 += (c0 - c1) * (d1 / (d1 - d0));
  if (c0.w() <= 1e-12 || c1.w() <= 1e-12) return;
  const Eigen::Vector2d half(0.5 * width, 0.5 * height);  // NDC to pixels
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
  const bool feather = samples == 1 && !axis_aligned;
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
  std::vector<OverlayVertex>& out = color.a == 255 && !feather ? lines : lines_blend;
  out.insert(out.end(), {a, b, c, b, d, c});
}

void Renderer::Impl::addPolyline(const ScenePolyline& line, const Eigen::Matrix4d& vp,
                                 bool edge_smoothing) {
  const std::size_t n = line.points.size();
  if (n < 2) return;
  // Points closer on screen than one and a half line widths to the last one kept add triangles
  // (which llvmpipe pays for one by one) but hardly a pixel (a 4 px chord of a 20 px radius
  // strays 0.1 px): dense paths are thinned here. Points behind a perspective camera are always
  // kept; the segment clipping handles them.
  const double min_px = std::max(2.0, 1.5 * line.width_px);
  const Eigen::Vector2d half(0.5 * width, 0.5 * height);
  clip.clear();
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
    clip.push_back(c);
  }
  for (std::size_t i = 0; i + 1 < clip.size(); ++i) {
    addSegment(clip[i], clip[i + 1], line.width_px, line.color, edge_smoothing);
  }
  if (line.closed && clip.size() > 2) {
    addSegment(clip.back(), clip.front(), line.width_px, line.color, edge_smoothing);
  }
}

void Renderer::Impl::addScreenQuad(float x0, float y0, float x1, float y1, const float uv[4],
                                   const Rgba8& c, std::vector<OverlayVertex>& out) const {
  auto vertex = [&](float x, float y, float u, float v) {
    OverlayVertex o;
    o.pos[0] = 2.0f * x / static_cast<float>(width) - 1.0f;
    o.pos[1] = 1.0f - 2.0f * y / static_cast<float>(height);
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

void Renderer::Impl::addText(const SceneText& t, const Camera& cam,
                             std::map<int, std::vector<OverlayVertex>>& by_font) {
  auto* entry = font(t.size_px);
  if (entry == nullptr || t.text.empty()) return;
  const FontAtlas& atlas = entry->first;
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
  auto& out = by_font[std::max(4, static_cast<int>(std::lround(t.size_px)))];
  if (t.background.a > 0) {
    const float pad = 0.25f * atlas.pixelHeight();
    const float solid[4] = {0.0f, kSolidHalfWidth, 0.0f, kSolidHalfWidth};
    addScreenQuad(x - pad, top - pad, x + w + pad, top + asc + desc + pad, solid, t.background,
                  text);
  }
  glyphs.clear();
  atlas.layout(t.text, x, top + asc, glyphs);
  for (const GlyphQuad& g : glyphs) {
    const float uv[4] = {g.s0, g.t0, g.s1, g.t1};
    addScreenQuad(g.x0, g.y0, g.x1, g.y1, uv, t.color, out);
  }
}

void Renderer::Impl::draw(const Scene& scene, const Camera& cam) {
  mesh.clear();
  mesh_blend.clear();
  lines.clear();
  lines_blend.clear();
  // A top view's first polygon, when it is an opaque axis-aligned rectangle (the lot's
  // surface), is nothing but a coloured rectangle under everything else: a scissored clear
  // fills it several times faster than llvmpipe shades it. The pixel range follows the
  // rasterizer's rule (pixel centres inside), so the result is the same.
  const std::optional<std::array<int, 4>> ground = groundRectangle(scene, cam);
  for (std::size_t i = ground ? 1 : 0; i < scene.polygons.size(); ++i) {
    const ScenePolygon& p = scene.polygons[i];
    addPolygon(p.points, p.z_m, p.color);
  }
  for (const SceneBox& b : scene.boxes) addBox(b);
  for (const ScenePrism& p : scene.prisms) addPrism(p);
  const Eigen::Matrix4d vp = cam.viewProjection();
  if (samples == 1 && !cam.perspective) {
    // Without multisampling, a top view smooths the edges of what it sees, the polygons and
    // the boxes' top faces, with a fading one-pixel outline in their own colour (the lines'
    // anti-aliasing). The outline sits on the face, so the depth test keeps it under anything
    // higher.
    ScenePolyline edge{{}, Rgba8{}, 1.0f, true};
    for (const ScenePolygon& p : scene.polygons) {
      if (p.color.a != 255) continue;
      edge.color = p.color;
      edge.points.clear();
      for (const Eigen::Vector2d& q : p.points) edge.points.emplace_back(q.x(), q.y(), p.z_m);
      addPolyline(edge, vp, true);
    }
    for (const SceneBox& b : scene.boxes) {
      if (b.color.a != 255) continue;
      edge = boxOutline(b.footprint, b.z_min_m + b.height_m, b.color, 1.0f);
      addPolyline(edge, vp, true);
    }
    for (const ScenePrism& p : scene.prisms) {
      if (p.color.a != 255) continue;
      edge.color = p.color;
      edge.points.clear();
      for (const Eigen::Vector2d& q : p.footprint) {
        edge.points.emplace_back(q.x(), q.y(), p.z_min_m + p.height_m);
      }
      addPolyline(edge, vp, true);
    }
  }
  for (const ScenePolyline& l : scene.lines) addPolyline(l, vp);
  for (const SceneArrow& a : scene.arrows) {
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
  text.clear();  // text backgrounds
  std::map<int, std::vector<OverlayVertex>> text_by_font;
  for (const SceneText& t : scene.texts) addText(t, cam, text_by_font);

  gl->BindFramebuffer(GL_FRAMEBUFFER, samples > 1 ? msaa_fbo : resolve_fbo);
  gl->Viewport(0, 0, width, height);
  // With a ground rectangle the whole framebuffer is cleared to its colour (llvmpipe's fast
  // path) and the background is put back around it by scissored clears of the thin margins
  // (a scissored clear is drawn like a quad: cheap only when small).
  const Rgba8& fill = ground ? scene.polygons.front().color : scene.background;
  gl->ClearColor(fill.r / 255.0f, fill.g / 255.0f, fill.b / 255.0f, 1.0f);
  gl->ClearDepth(1.0);
  gl->DepthMask(GL_TRUE);
  gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (ground) {
    const std::array<int, 4>& r = *ground;  // x, y (image rows from the top), width, height
    const std::array<std::array<int, 4>, 4> margins = {{
        {0, 0, width, r[1]},                             // above
        {0, r[1] + r[3], width, height - r[1] - r[3]},   // below
        {0, r[1], r[0], r[3]},                           // left
        {r[0] + r[2], r[1], width - r[0] - r[2], r[3]},  // right
    }};
    const Rgba8& bg = scene.background;
    gl->ClearColor(bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f);
    gl->Enable(GL_SCISSOR_TEST);
    for (const std::array<int, 4>& m : margins) {
      if (m[2] <= 0 || m[3] <= 0) continue;
      gl->Scissor(m[0], m[1], m[2], m[3]);  // image rows are framebuffer rows (y is flipped)
      gl->Clear(GL_COLOR_BUFFER_BIT);
    }
    gl->Disable(GL_SCISSOR_TEST);
  }
  gl->BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl->Enable(GL_DEPTH_TEST);
  gl->DepthFunc(GL_LEQUAL);
  if (samples > 1) gl->Enable(GL_MULTISAMPLE);

  // One upload per frame; each batch is a range of the buffer.
  auto upload = [this](GLuint vao, GLuint vbo, const auto& first, const auto& second) {
    using Vertex = typename std::decay_t<decltype(first)>::value_type;
    gl->BindVertexArray(vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, vbo);
    const auto bytes = static_cast<GLsizeiptr>((first.size() + second.size()) * sizeof(Vertex));
    gl->BufferData(GL_ARRAY_BUFFER, bytes, nullptr, GL_STREAM_DRAW);
    gl->BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(first.size() * sizeof(Vertex)),
                      first.data());
    gl->BufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(first.size() * sizeof(Vertex)),
                      static_cast<GLsizeiptr>(second.size() * sizeof(Vertex)), second.data());
  };
  auto drawRange = [this](std::size_t first, std::size_t count, bool blend) {
    if (count == 0) return;
    if (blend) {
      gl->Enable(GL_BLEND);
    } else {
      gl->Disable(GL_BLEND);
    }
    gl->DrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(count));
  };

  if (!mesh.empty() || !mesh_blend.empty()) {
    // Flipping y in clip space makes row 0 of the framebuffer the image's top row.
    Eigen::Matrix4f flip = Eigen::Matrix4f::Identity();
    flip(1, 1) = -1.0f;
    const Eigen::Matrix4f m = flip * vp.cast<float>();
    const Eigen::Vector3d light = def.light_direction.normalized();
    const double ambient = std::clamp(def.ambient, 0.0, 1.0);
    const double up = ambient + (1.0 - ambient) * std::max(light.z(), 0.0);
    if (cam.perspective) {
      gl->UseProgram(programs.lit);
      gl->UniformMatrix4fv(programs.lit_view_proj, 1, GL_FALSE, m.data());
      gl->Uniform3f(programs.light, static_cast<float>(light.x()), static_cast<float>(light.y()),
                    static_cast<float>(light.z()));
      gl->Uniform1f(programs.ambient, static_cast<float>(ambient));
      gl->Uniform1f(programs.up_factor, static_cast<float>(std::max(up, 1e-3)));
    } else {
      gl->UseProgram(programs.flat);
      gl->UniformMatrix4fv(programs.flat_view_proj, 1, GL_FALSE, m.data());
    }
    upload(mesh_vao, mesh_vbo, mesh, mesh_blend);
    drawRange(0, mesh.size(), false);
    drawRange(mesh.size(), mesh_blend.size(), true);
  }

  if (!lines.empty() || !lines_blend.empty()) {
    gl->UseProgram(programs.solid);
    // Lines are depth-tested (boxes hide what lies under them) but write no depth, so crossing
    // lines simply paint in list order.
    gl->DepthMask(GL_FALSE);
    upload(overlay_vao, overlay_vbo, lines, lines_blend);
    drawRange(0, lines.size(), false);
    drawRange(lines.size(), lines_blend.size(), true);
  }
  gl->Disable(GL_DEPTH_TEST);
  if (!text.empty()) {
    gl->UseProgram(programs.solid);
    upload(overlay_vao, overlay_vbo, text, std::vector<OverlayVertex>{});
    drawRange(0, text.size(), true);
  }
  if (!text_by_font.empty()) {
    gl->UseProgram(programs.text);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindVertexArray(overlay_vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, overlay_vbo);
    for (auto& [size, verts] : text_by_font) {
      gl->BindTexture(GL_TEXTURE_2D, fonts.at(size).second);
      gl->BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(verts.size() * sizeof(OverlayVertex)),
                     verts.data(), GL_STREAM_DRAW);
      drawRange(0, verts.size(), true);
    }
  }
  gl->DepthMask(GL_TRUE);
  gl->BindVertexArray(0);

  if (samples > 1) {
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo);
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo);
    gl->BlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  gl->BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo);
}

Renderer::Renderer(const RenderDef& def) : Renderer(def, createOffscreenContext(def.context)) {}

Renderer::Renderer(const RenderDef& def, std::unique_ptr<OffscreenContext> context)
    : impl_(std::make_unique<Impl>()) {
  if (!context) throw Error("renderer: no GL context");
  if (def.width_px <= 0 || def.height_px <= 0) {
    throw Error("renderer: image size must be positive, got " + std::to_string(def.width_px) + "x" +
                std::to_string(def.height_px));
  }
  impl_->def = def;
  impl_->context = std::move(context);
  impl_->gl = &impl_->context->gl();
  if (!def.font_path.empty()) {
    impl_->font_data = readFontFile(def.font_path);
  } else if (!def.font_family.empty()) {
    impl_->font_data = readFontFile(findFontFile(def.font_family));
  }
  const CurrentContext current(*impl_->context);
  impl_->init();
  impl_->width = def.width_px;
  impl_->height = def.height_px;
  impl_->allocateFramebuffers();
}

Renderer::~Renderer() {
  if (!impl_ || !impl_->context) return;
  impl_->ensureCurrent();
  impl_->releaseFramebuffers();
  const GlFunctions& gl = *impl_->gl;
  for (auto& [size, entry] : impl_->fonts) gl.DeleteTextures(1, &entry.second);
  gl.DeleteBuffers(1, &impl_->mesh_vbo);
  gl.DeleteBuffers(1, &impl_->overlay_vbo);
  gl.DeleteVertexArrays(1, &impl_->mesh_vao);
  gl.DeleteVertexArrays(1, &impl_->overlay_vao);
  impl_->programs.destroy(gl);
}

int Renderer::width() const { return impl_->width; }
int Renderer::height() const { return impl_->height; }
int Renderer::samples() const { return impl_->samples; }
std::string Renderer::description() const { return impl_->context->description(); }
ContextBackend Renderer::backend() const { return impl_->context->backend(); }

void Renderer::setSize(int width_px, int height_px) {
  if (width_px <= 0 || height_px <= 0) {
    throw Error("renderer: image size must be positive, got " + std::to_string(width_px) + "x" +
                std::to_string(height_px));
  }
  if (width_px == impl_->width && height_px == impl_->height) return;
  const CurrentContext current(*impl_->context);
  impl_->width = width_px;
  impl_->height = height_px;
  impl_->allocateFramebuffers();
}

Camera Renderer::camera(const Scene& scene, const CameraDef& camera_def) const {
  return makeCamera(camera_def, scene, impl_->width, impl_->height);
}

void Renderer::render(const Scene& scene, const CameraDef& camera_def, RgbImage& out) {
  if (out.width != impl_->width || out.height != impl_->height) {
    out.resize(impl_->width, impl_->height);
  }
  renderInto(scene, camera_def, out, 0);
}

void Renderer::renderInto(const Scene& scene, const CameraDef& camera_def, RgbImage& out,
                          int x_offset_px) {
  if (out.height != impl_->height || x_offset_px < 0 || x_offset_px + impl_->width > out.width ||
      out.pixels.size() != static_cast<std::size_t>(out.width) * out.height * 3) {
    throw Error("renderer: a " + std::to_string(impl_->width) + "x" +
                std::to_string(impl_->height) + " view does not fit at column " +
                std::to_string(x_offset_px) + " of a " + std::to_string(out.width) + "x" +
                std::to_string(out.height) + " image");
  }
  const CurrentContext current(*impl_->context);
  impl_->draw(scene, camera(scene, camera_def));
  // llvmpipe reads RGBA with a plain copy but converts to RGB pixel by pixel (~10x slower):
  // read RGBA and drop alpha here.
  const int w = impl_->width;
  const int h = impl_->height;
  std::vector<std::uint8_t>& rgba = impl_->rgba;
  rgba.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  impl_->gl->ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  checkGl(*impl_->gl, "render");
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* src = rgba.data() + static_cast<std::size_t>(y) * w * 4;
    std::uint8_t* dst =
        out.pixels.data() + (static_cast<std::size_t>(y) * out.width + x_offset_px) * 3;
    for (int x = 0; x < w; ++x, src += 4, dst += 3) {
      dst[0] = src[0];
      dst[1] = src[1];
      dst[2] = src[2];
    }
  }
}

}  // namespace parksim
