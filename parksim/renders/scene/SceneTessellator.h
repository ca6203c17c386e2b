#pragma once
// Turns a Scene seen through a Camera into a DrawList: boxes, prisms, polygons and arrow heads
// into triangles; polylines and arrow shafts into ribbons of constant width in pixels; text into
// glyph quads; a top view's ground rectangle into a clear. No GL: the result is plain data, and
// the Renderer only uploads and draws it.
//
// A tessellator keeps its scratch memory between images, so steady-state use does not allocate.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "parksim/renders/scene/Camera.h"
#include "parksim/renders/scene/DrawList.h"
#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/text/FontCache.h"

namespace parksim {

struct TessellationDef {
  /// Samples per pixel the image is drawn with. 1: line ribbons grow by half a pixel a side
  /// for the shader's coverage fade, and a top view outlines its faces with fading one-pixel
  /// lines (anti-aliasing without multisampling).
  int samples = 1;
  /// Direction towards the light in the world frame (normalized on use).
  Eigen::Vector3d light_direction{0.35, -0.55, 0.75};
  /// Lit views: share of a face's colour independent of the light direction, 0..1.
  double ambient = 0.45;
  /// A top view's first polygon, when it is an opaque axis-aligned rectangle (the lot), is
  /// filled by the clear (DrawList::ground) instead of drawn. Off for a scene drawn over a
  /// backdrop, which clears nothing.
  bool ground_clear = true;
};

class SceneTessellator {
 public:
  /// Fills `out` (emptied first) for an image of the camera's size. Text is laid out with
  /// `fonts`' atlases (packed on first use); without a font, text is left out.
  void tessellate(const Scene& scene, const Camera& camera, const TessellationDef& def,
                  FontCache& fonts, DrawList& out);

 private:
  void addTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& n, const Rgba8& color);
  void addBox(const SceneBox& box);
  void addPrism(const ScenePrism& prism);
  void addPolygon(const std::vector<Eigen::Vector2d>& pts, double z, const Rgba8& color);
  void addSegment(Eigen::Vector4d c0, Eigen::Vector4d c1, float width_px, const Rgba8& color,
                  bool edge_smoothing = false);
  void addPolyline(const ScenePolyline& line, const Eigen::Matrix4d& vp,
                   bool edge_smoothing = false);
  void addEdgeOutlines(const Scene& scene, const Eigen::Matrix4d& vp);
  void addArrow(const SceneArrow& arrow, const Eigen::Matrix4d& vp);
  void addScreenQuad(float x0, float y0, float x1, float y1, const float uv[4], const Rgba8& c,
                     std::vector<OverlayVertex>& out) const;
  void addText(const SceneText& text, const Camera& cam, FontCache& fonts);
  void setUniforms(const Camera& cam, const TessellationDef& def);

  DrawList* out_ = nullptr;  // the list being filled
  int samples_ = 1;
  // Scratch, kept between images.
  std::vector<Eigen::Vector4d> clip_;
  std::vector<GlyphQuad> glyphs_;
  ScenePolyline edge_;
};

/// The pixel rectangle a top view's first polygon covers, when that polygon is an opaque
/// axis-aligned rectangle (the lot's surface); unset otherwise (and for perspective cameras).
/// Pixel (i, j) is covered when its centre lies inside, the rasterizer's rule.
std::optional<PixelRect> groundRectangle(const Scene& scene, const Camera& camera);

}  // namespace parksim
