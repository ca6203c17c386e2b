#include "parksim/renders/gl/Renderer.h"

#include <algorithm>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/renders/gl/RendererImpl.h"
#include "parksim/renders/scene/DrawListChange.h"

// A film's view (Renderer.h): the lot drawn once into a kept backdrop and copied back under
// each frame's front, and renderChanges, which draws and reads back only where the front
// changed.

namespace parksim {

namespace {

void checkLayers(const Scene& backdrop, const Scene& scene) {
  if (scene.extent != backdrop.extent || scene.extent_top_m != backdrop.extent_top_m) {
    throw Error("renderer: a scene drawn over a backdrop must have the backdrop's extent");
  }
}

// The rows of `rects`, sorted and merged where they meet.
std::vector<RowSpan> rowsOf(const std::vector<PixelRect>& rects) {
  std::vector<RowSpan> rows;
  for (const PixelRect& r : rects) rows.push_back({r.y, r.y + r.height});
  std::sort(rows.begin(), rows.end(),
            [](const RowSpan& a, const RowSpan& b) { return a.begin < b.begin; });
  std::vector<RowSpan> merged;
  for (const RowSpan& s : rows) {
    if (!merged.empty() && s.begin <= merged.back().end) {
      merged.back().end = std::max(merged.back().end, s.end);
    } else {
      merged.push_back(s);
    }
  }
  return merged;
}

// The scissor test on while it lives: whatever throws, later clears and copies are whole.
class Scissor {
 public:
  Scissor(const GlFunctions& gl, const PixelRect& r) : gl_(gl) {
    gl_.Enable(GL_SCISSOR_TEST);
    gl_.Scissor(r.x, r.y, r.width, r.height);
  }
  ~Scissor() { gl_.Disable(GL_SCISSOR_TEST); }
  Scissor(const Scissor&) = delete;
  Scissor& operator=(const Scissor&) = delete;

 private:
  const GlFunctions& gl_;
};

}  // namespace

// Leaves the drawing framebuffer bound and holding the backdrop, drawn now or copied back.
void Renderer::Impl::drawBackdrop(const Scene& backdrop, const Camera& cam) {
  if (backdropKept(backdrop, cam)) {
    copyFramebuffer(backdrop_fbo, drawFramebuffer());
    return;
  }
  backdrop_scene.reset();  // until it is drawn and kept
  if (backdrop_fbo == 0) {
    gl->GenFramebuffers(1, &backdrop_fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, backdrop_fbo);
    storage(backdrop_color, GL_RGBA8, samples);
    gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                backdrop_color);
    storage(backdrop_depth, GL_DEPTH_COMPONENT24, samples);
    gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                backdrop_depth);
    try {
      complete("backdrop");
    } catch (...) {
      releaseBackdrop();
      throw;
    }
  }
  tessellator.tessellate(backdrop, cam, tessellation(), fonts, list);
  clear(list);
  drawItems(list);
  copyFramebuffer(drawFramebuffer(), backdrop_fbo);
  checkGl(*gl, "backdrop");
  backdrop_scene = backdrop;
  backdrop_camera = cam;
  ++backdrops_drawn;
}

void Renderer::Impl::releaseBackdrop() {
  gl->DeleteFramebuffers(1, &backdrop_fbo);
  const GLuint rbs[] = {backdrop_color, backdrop_depth};
  gl->DeleteRenderbuffers(2, rbs);
  backdrop_fbo = backdrop_color = backdrop_depth = 0;
  backdrop_scene.reset();
}

long Renderer::backdropsDrawn() const { return impl_->backdrops_drawn; }

void Renderer::renderInto(const Scene& backdrop, const Scene& scene, const CameraDef& camera_def,
                          RgbaImage& out, int x_offset_px) {
  checkFits(out, impl_->width, impl_->height, x_offset_px);
  checkLayers(backdrop, scene);
  const Camera cam = camera(scene, camera_def);
  const CurrentContext current(*impl_->context);
  impl_->drawBackdrop(backdrop, cam);
  TessellationDef front = tessellationDef();
  front.ground_clear = false;  // nothing is cleared over the backdrop
  impl_->tessellator.tessellate(scene, cam, front, impl_->fonts, impl_->list);
  impl_->drawItems(impl_->list);
  impl_->resolve();
  impl_->readRgba(out.pixels.data() + static_cast<std::size_t>(x_offset_px) * 4, out.width);
  std::swap(impl_->list, impl_->last_front);
  impl_->front_kept = true;
}

std::vector<RowSpan> Renderer::renderChanges(const Scene& backdrop, const Scene& scene,
                                             const CameraDef& camera_def, RgbaImage& out,
                                             int x_offset_px) {
  Impl& m = *impl_;
  checkFits(out, m.width, m.height, x_offset_px);
  checkLayers(backdrop, scene);
  const Camera cam = camera(scene, camera_def);
  if (!m.front_kept || !m.backdropKept(backdrop, cam)) {
    renderInto(backdrop, scene, camera_def, out, x_offset_px);
    return {{0, m.height}};
  }
  const CurrentContext current(*m.context);
  TessellationDef front = tessellationDef();
  front.ground_clear = false;
  m.tessellator.tessellate(scene, cam, front, m.fonts, m.list);
  const std::vector<PixelRect> rects = changedRects(m.last_front, m.list);
  // Until this image is whole, the framebuffer holds neither front: an error below must not
  // leave the next call building on it.
  m.front_kept = false;
  // Each rectangle gets the backdrop back, then the whole front drawn inside it: the same
  // pixels as drawing everything, as a pixel's value depends only on what covers it.
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const PixelRect& r = rects[i];
    m.copyRect(m.backdrop_fbo, m.drawFramebuffer(), r);
    m.gl->BindFramebuffer(GL_FRAMEBUFFER, m.drawFramebuffer());
    m.gl->Viewport(0, 0, m.width, m.height);
    {
      const Scissor scissor(*m.gl, r);
      m.drawItems(m.list, i == 0);
    }
    m.resolveRect(r);
  }
  const std::vector<RowSpan> merged = rowsOf(rects);
  m.gl->BindFramebuffer(GL_READ_FRAMEBUFFER, m.resolve_fbo);
  for (const RowSpan& s : merged) {
    m.readRows(out.pixels.data() + static_cast<std::size_t>(x_offset_px) * 4, out.width, s.begin,
               s.end);
  }
  checkGl(*m.gl, "render");
  std::swap(m.list, m.last_front);
  m.front_kept = true;
  return merged;
}

}  // namespace parksim
