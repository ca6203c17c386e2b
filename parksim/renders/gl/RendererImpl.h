#pragma once
// Internal to parksim_render (not installed): the renderer's state, shared by Renderer.cpp (the
// context, framebuffers, buffers and drawing a DrawList) and RendererLayers.cpp (a film's view:
// the kept backdrop, and the rows that changed).

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parksim/renders/gl/GlFunctions.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/gl/RendererPrograms.h"
#include "parksim/renders/scene/DrawList.h"
#include "parksim/renders/scene/SceneTessellator.h"
#include "parksim/renders/text/FontCache.h"

namespace parksim {

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

struct Renderer::Impl {
  RenderDef def;
  std::unique_ptr<OffscreenContext> context;
  const GlFunctions* gl = nullptr;  // the context's entry points
  FontCache fonts;
  std::map<int, GLuint> font_textures;  // by the atlas's pixel height

  int width = 0;
  int height = 0;
  int samples = 1;
  GLint max_samples = 1;
  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0;
  GLuint resolve_fbo = 0, resolve_color = 0, resolve_depth = 0;
  // The kept backdrop (renderInto with a backdrop): its colour and depth at the drawing
  // framebuffer's size and samples, made on first use; and what it shows.
  GLuint backdrop_fbo = 0, backdrop_color = 0, backdrop_depth = 0;
  std::optional<Scene> backdrop_scene;
  Camera backdrop_camera;
  long backdrops_drawn = 0;
  RendererPrograms programs;
  GLuint mesh_vao = 0, mesh_vbo = 0, overlay_vao = 0, overlay_vbo = 0;
  // Bytes each vertex buffer holds: its storage is kept and grown, not made anew each image
  // (llvmpipe allocates and zeroes new storage, page by page).
  std::size_t mesh_capacity = 0, overlay_capacity = 0;
  std::vector<const std::vector<MeshVertex>*> mesh_batches;
  std::vector<const std::vector<OverlayVertex>*> overlay_batches;

  // Kept between images, so steady-state drawing does not allocate.
  SceneTessellator tessellator;
  DrawList list;
  // The front last drawn over the kept backdrop, while the drawing framebuffer still holds that
  // image (front_kept): renderChanges draws only where the next front differs from it.
  DrawList last_front;
  bool front_kept = false;
  std::vector<std::uint8_t> rgba;  // read-back buffer

  void init();
  void allocateFramebuffers();
  void releaseFramebuffers();
  void ensureCurrent() {
    if (!context->isCurrent()) context->makeCurrent();
  }
  GLuint fontTexture(int font_px);

  GLuint drawFramebuffer() const { return samples > 1 ? msaa_fbo : resolve_fbo; }
  TessellationDef tessellation() const { return {samples, def.light_direction, def.ambient}; }
  void storage(GLuint& rb, GLenum format, int n);  // a renderbuffer of the image's size
  void complete(const char* which);  // throws unless the bound framebuffer is complete
  void releaseBackdrop();
  void draw(const DrawList& list);
  void drawWhole(const Scene& scene, const Camera& cam) {  // render() and renderInto(scene)
    tessellator.tessellate(scene, cam, tessellation(), fonts, list);
    draw(list);
  }
  void clear(const DrawList& list);
  // `upload` false: the list's vertices are in the buffers already (drawn once this image).
  void drawItems(const DrawList& list, bool upload = true);
  void resolve();
  void resolveRect(const PixelRect& r);
  bool backdropKept(const Scene& backdrop, const Camera& cam) const {
    return backdrop_scene && backdrop_camera == cam && *backdrop_scene == backdrop;
  }
  void drawBackdrop(const Scene& backdrop, const Camera& cam);
  void copyFramebuffer(GLuint from, GLuint to);
  void copyRect(GLuint from, GLuint to, const PixelRect& r);
  // The resolved image, RGBA, into `dst` whose rows are row_length_px pixels apart; or only
  // rows [y0, y1), into the same places.
  void readRgba(std::uint8_t* dst, int row_length_px) { readRows(dst, row_length_px, 0, height); }
  void readRows(std::uint8_t* dst, int row_length_px, int y0, int y1);
  template <class Vertex>
  void upload(GLuint vbo, std::size_t& capacity,
              const std::vector<const std::vector<Vertex>*>& batches);
  void drawRange(std::size_t first, std::size_t count, bool blend);
  void useMeshProgram(const DrawList& list);
};

/// Throws Error unless a view of width x height fits at column x_offset_px of `out`.
void checkFits(const RgbaImage& out, int width, int height, int x_offset_px);

}  // namespace parksim
