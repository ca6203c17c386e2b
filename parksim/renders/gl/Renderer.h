#pragma once
// Draws a Scene through a camera into an RGB image (films: RGBA), off screen. One renderer owns one
// GL context and its framebuffers, vertex buffers and font textures, and reuses them for every
// image it draws: per frame it tessellates the scene into a DrawList without GL
// (SceneTessellator.h), uploads the vertices, draws and reads back.
//
// Anti-aliasing is multisampling (an MSAA framebuffer resolved by a blit). With multisampling
// off, lines and text are still anti-aliased (coverage fades over their outermost pixel) and a
// top view smooths polygon and box edges with a fading outline; only perspective edges alias.
// Top-down views are unlit, so fully covered pixels carry their colour exactly; perspective
// views are lit by one directional light scaled so that upward faces keep their exact colour
// and sides darken.
//
// Not thread-safe; use a renderer from one thread at a time (it makes its context current on
// the calling thread while it draws, and releases it afterwards).

#include <memory>
#include <string>

#include <Eigen/Core>

#include "parksim/renders/gl/OffscreenContext.h"
#include "parksim/renders/image/Image.h"
#include "parksim/renders/scene/Camera.h"
#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneTessellator.h"
#include "parksim/renders/text/FontLookup.h"

namespace parksim {

struct RenderDef {
  int width_px = 640;   ///< image width, pixels
  int height_px = 480;  ///< image height, pixels
  /// Samples per pixel for anti-aliasing; 0 or 1 turns it off. Clamped to what the GL offers
  /// (4 on llvmpipe).
  int msaa_samples = 4;
  /// TrueType font file for text; empty: font_family's file, found through fontconfig.
  std::string font_path;
  /// Font family (a fontconfig pattern) when font_path is empty; both empty: text is not drawn.
  std::string font_family = kDefaultFontFamily;
  /// Direction towards the light in the world frame (normalized on use).
  Eigen::Vector3d light_direction{0.35, -0.55, 0.75};
  /// Lit views: share of a face's colour independent of the light direction, 0..1.
  double ambient = 0.45;
  ContextDef context;
};

class Renderer {
 public:
  /// Creates the context (createOffscreenContext(def.context)), framebuffers and shaders.
  /// Throws Error when any of them fails or the font cannot be found or read.
  explicit Renderer(const RenderDef& def = {});
  /// Uses a context made beforehand by createOffscreenContext (its backend is then known first).
  Renderer(const RenderDef& def, std::unique_ptr<OffscreenContext> context);
  ~Renderer();

  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  int width() const;
  int height() const;
  /// Samples per pixel actually used (1: no anti-aliasing).
  int samples() const;
  /// The GL context's description ("EGL (device: software): 4.5 (Core Profile) Mesa ...").
  std::string description() const;
  /// The backend that made the context (never kAuto).
  ContextBackend backend() const;

  /// Changes the image size; reallocates framebuffers only when it differs.
  void setSize(int width_px, int height_px);

  /// The camera render() uses for `scene` at the current size.
  Camera camera(const Scene& scene, const CameraDef& camera_def) const;

  /// The tessellation render() uses at the current size: the samples actually used, and
  /// RenderDef's light. With camera(), SceneTessellator gives the DrawList this renderer draws.
  TessellationDef tessellationDef() const;

  /// Draws `scene` and reads it back into `out`, resized to width() x height().
  void render(const Scene& scene, const CameraDef& camera_def, RgbImage& out);

  /// Draws `scene` into columns [x_offset_px, x_offset_px + width()) of `out`, whose height must
  /// be height(): for views side by side in one image. Throws Error when it does not fit. RGBA,
  /// as the GL reads back: a film's frame costs its caller a copy and no conversion.
  void renderInto(const Scene& scene, const CameraDef& camera_def, RgbaImage& out, int x_offset_px);

  /// Draws `backdrop`, then `scene` over it, into columns [x_offset_px, x_offset_px + width())
  /// of `out`: for films, whose lot stays while the robot moves (buildSceneLayers). The camera
  /// frames `scene`, whose extent must be the backdrop's (Error otherwise); its first polygon
  /// is drawn, never taken for a ground to clear. The backdrop's pixels and depth are kept,
  /// and while the next call brings an equal backdrop through the same camera they are copied
  /// back instead of drawn again: the image never depends on what was drawn before.
  /// The picture is one scene's (appendScene) but for the order: all of the backdrop is drawn
  /// before any of `scene`, so a front item lies over backdrop lines it touches where one scene
  /// draws them over it (solid lines and soft edges go before translucent lines in one scene):
  /// the arrows' shafts over the planned path, the robot's soft edge over the lines beside it. A
  /// few dozen pixels of a 640x480 film frame differ from one scene's picture.
  void renderInto(const Scene& backdrop, const Scene& scene, const CameraDef& camera_def,
                  RgbaImage& out, int x_offset_px);

  /// renderInto(backdrop, scene, ...) for a film's next frame: only the rows that can differ
  /// from the image the last renderChanges or renderInto(backdrop, scene, ...) drew are drawn
  /// and read back into `out`, and returned, sorted and apart. `out`'s other rows are not
  /// written: they are that last image's, which the caller keeps at the same x_offset_px (a
  /// film's PNG encoder does). All rows when there is nothing to build on: the first call, a new
  /// size, backdrop or camera, or anything else drawn since. The rows written are renderInto's
  /// bytes. Throws Error as renderInto does.
  std::vector<RowSpan> renderChanges(const Scene& backdrop, const Scene& scene,
                                     const CameraDef& camera_def, RgbaImage& out, int x_offset_px);

  /// How many times a backdrop was drawn rather than copied back (once per change of it).
  long backdropsDrawn() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
