#include "parksim/renders/gl/Renderer.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/renders/gl/RendererImpl.h"

// The context, framebuffers, buffers and shaders, and drawing a DrawList; a film's layered view
// is in RendererLayers.cpp.

namespace parksim {

namespace {

void clearColor(const GlFunctions& gl, const Rgba8& c) {
  gl.ClearColor(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
}

}  // namespace

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
  releaseBackdrop();
}

void Renderer::Impl::storage(GLuint& rb, GLenum format, int n) {
  gl->GenRenderbuffers(1, &rb);
  gl->BindRenderbuffer(GL_RENDERBUFFER, rb);
  if (n > 1) {
    gl->RenderbufferStorageMultisample(GL_RENDERBUFFER, n, format, width, height);
  } else {
    gl->RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  }
}

void Renderer::Impl::complete(const char* which) {
  if (gl->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error(std::string("renderer: ") + which + " framebuffer is incomplete");
  }
}

void Renderer::Impl::allocateFramebuffers() {
  front_kept = false;
  releaseFramebuffers();
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

GLuint Renderer::Impl::fontTexture(int font_px) {
  auto it = font_textures.find(font_px);
  if (it != font_textures.end()) return it->second;
  const FontAtlas& atlas = fonts.atlas(font_px);
  GLuint tex = 0;
  gl->GenTextures(1, &tex);
  gl->BindTexture(GL_TEXTURE_2D, tex);
  gl->TexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.atlasWidth(), atlas.atlasHeight(), 0, GL_RED,
                 GL_UNSIGNED_BYTE, atlas.bitmap().data());
  gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  font_textures.emplace(font_px, tex);
  return tex;
}

// One upload per buffer and image, before any draw: each batch is a range of the buffer, one
// after the other. The last image's draws are finished (it was read back), so overwriting the
// storage does not wait for them; a backdrop drawn just before is finished too, as it was
// copied into its framebuffer.
template <class Vertex>
void Renderer::Impl::upload(GLuint vbo, std::size_t& capacity,
                            const std::vector<const std::vector<Vertex>*>& batches) {
  std::size_t bytes = 0;
  for (const std::vector<Vertex>* b : batches) bytes += b->size() * sizeof(Vertex);
  gl->BindBuffer(GL_ARRAY_BUFFER, vbo);
  if (bytes > capacity) {
    capacity = std::max(bytes, 2 * capacity);
    gl->BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_DRAW);
  }
  std::size_t offset = 0;
  for (const std::vector<Vertex>* b : batches) {
    const std::size_t n = b->size() * sizeof(Vertex);
    if (n > 0) {
      gl->BufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(n),
                        b->data());
    }
    offset += n;
  }
}

void Renderer::Impl::drawRange(std::size_t first, std::size_t count, bool blend) {
  if (count == 0) return;
  if (blend) {
    gl->Enable(GL_BLEND);
  } else {
    gl->Disable(GL_BLEND);
  }
  gl->DrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(count));
}

void Renderer::Impl::clear(const DrawList& dl) {
  front_kept = false;
  gl->BindFramebuffer(GL_FRAMEBUFFER, drawFramebuffer());
  gl->Viewport(0, 0, width, height);
  // With a ground rectangle the whole framebuffer is cleared to its colour (llvmpipe's fast
  // path) and the background is put back around it by scissored clears of the thin margins
  // (a scissored clear is drawn like a quad: cheap only when small).
  clearColor(*gl, dl.clear_color);
  gl->ClearDepth(1.0);
  gl->DepthMask(GL_TRUE);
  gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (dl.ground) {
    clearColor(*gl, dl.background);
    gl->Enable(GL_SCISSOR_TEST);
    for (const PixelRect& m : dl.groundMargins()) {
      if (m.width <= 0 || m.height <= 0) continue;
      gl->Scissor(m.x, m.y, m.width, m.height);  // image rows are framebuffer rows (y is flipped)
      gl->Clear(GL_COLOR_BUFFER_BIT);
    }
    gl->Disable(GL_SCISSOR_TEST);
  }
}

void Renderer::Impl::useMeshProgram(const DrawList& dl) {
  if (dl.lit) {
    gl->UseProgram(programs.lit);
    gl->UniformMatrix4fv(programs.lit_view_proj, 1, GL_FALSE, dl.view_proj.data());
    gl->Uniform3f(programs.light, dl.light[0], dl.light[1], dl.light[2]);
    gl->Uniform1f(programs.ambient, dl.ambient);
    gl->Uniform1f(programs.up_factor, dl.up_factor);
  } else {
    gl->UseProgram(programs.flat);
    gl->UniformMatrix4fv(programs.flat_view_proj, 1, GL_FALSE, dl.view_proj.data());
  }
}

void Renderer::Impl::draw(const DrawList& dl) {
  clear(dl);
  drawItems(dl);
  resolve();
}

// Draws into the drawing framebuffer, which is bound, over what it holds.
void Renderer::Impl::drawItems(const DrawList& dl, bool upload_vertices) {
  gl->BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl->Enable(GL_DEPTH_TEST);
  gl->DepthFunc(GL_LEQUAL);
  if (samples > 1) gl->Enable(GL_MULTISAMPLE);

  if (!dl.mesh.empty() || !dl.mesh_blend.empty()) {
    useMeshProgram(dl);
    if (upload_vertices) {
      mesh_batches.assign({&dl.mesh, &dl.mesh_blend});
      upload(mesh_vbo, mesh_capacity, mesh_batches);
    }
    gl->BindVertexArray(mesh_vao);
    drawRange(0, dl.mesh.size(), false);
    drawRange(dl.mesh.size(), dl.mesh_blend.size(), true);
  }
  // Lines, text boxes and glyphs share the overlay buffer, in that order.
  if (upload_vertices) {
    overlay_batches.assign({&dl.lines, &dl.lines_blend, &dl.text_boxes});
    for (const GlyphBatch& batch : dl.glyphs) overlay_batches.push_back(&batch.vertices);
    upload(overlay_vbo, overlay_capacity, overlay_batches);
  }
  gl->BindVertexArray(overlay_vao);
  std::size_t first = 0;
  if (!dl.lines.empty() || !dl.lines_blend.empty()) {
    gl->UseProgram(programs.solid);
    // Lines are depth-tested (boxes hide what lies under them) but write no depth, so crossing
    // lines simply paint in list order.
    gl->DepthMask(GL_FALSE);
    drawRange(first, dl.lines.size(), false);
    drawRange(first + dl.lines.size(), dl.lines_blend.size(), true);
  }
  first += dl.lines.size() + dl.lines_blend.size();
  gl->Disable(GL_DEPTH_TEST);
  if (!dl.text_boxes.empty()) {
    gl->UseProgram(programs.solid);
    drawRange(first, dl.text_boxes.size(), true);
  }
  first += dl.text_boxes.size();
  if (!dl.glyphs.empty()) {
    gl->UseProgram(programs.text);
    gl->ActiveTexture(GL_TEXTURE0);
    for (const GlyphBatch& batch : dl.glyphs) {
      gl->BindTexture(GL_TEXTURE_2D, fontTexture(batch.font_px));
      drawRange(first, batch.vertices.size(), true);
      first += batch.vertices.size();
    }
  }
  gl->DepthMask(GL_TRUE);
  gl->BindVertexArray(0);
}

void Renderer::Impl::resolveRect(const PixelRect& r) {
  if (samples > 1) {
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo);
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo);
    gl->BlitFramebuffer(r.x, r.y, r.x + r.width, r.y + r.height, r.x, r.y, r.x + r.width,
                        r.y + r.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
}

void Renderer::Impl::resolve() {
  resolveRect({0, 0, width, height});
  gl->BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo);
}

// Colour and depth, same size and samples, of the whole image or a rectangle given explicitly
// (not scissored): llvmpipe then copies the memory, with no shading.
void Renderer::Impl::copyRect(GLuint from, GLuint to, const PixelRect& r) {
  gl->BindFramebuffer(GL_READ_FRAMEBUFFER, from);
  gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
  gl->BlitFramebuffer(r.x, r.y, r.x + r.width, r.y + r.height, r.x, r.y, r.x + r.width,
                      r.y + r.height, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

void Renderer::Impl::copyFramebuffer(GLuint from, GLuint to) {
  front_kept = false;
  copyRect(from, to, {0, 0, width, height});
  gl->BindFramebuffer(GL_FRAMEBUFFER, drawFramebuffer());
  gl->Viewport(0, 0, width, height);
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
    impl_->fonts = FontCache(readFontFile(def.font_path));
  } else if (!def.font_family.empty()) {
    impl_->fonts = FontCache(readFontFile(findFontFile(def.font_family)));
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
  for (auto& [size, texture] : impl_->font_textures) gl.DeleteTextures(1, &texture);
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

TessellationDef Renderer::tessellationDef() const { return impl_->tessellation(); }

void Renderer::render(const Scene& scene, const CameraDef& camera_def, RgbImage& out) {
  if (out.width != impl_->width || out.height != impl_->height) {
    out.resize(impl_->width, impl_->height);
  }
  const CurrentContext current(*impl_->context);
  impl_->drawWhole(scene, camera(scene, camera_def));
  // llvmpipe reads RGBA with a plain copy but converts to RGB pixel by pixel (~10x slower):
  // read RGBA and drop alpha here.
  impl_->rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  impl_->readRgba(impl_->rgba.data(), out.width);
  rgbaToRgb(impl_->rgba.data(), out.pixels.data(),
            static_cast<std::size_t>(out.width) * out.height);
}

void checkFits(const RgbaImage& out, int width, int height, int x_offset_px) {
  if (out.height != height || x_offset_px < 0 || x_offset_px + width > out.width ||
      out.pixels.size() != static_cast<std::size_t>(out.width) * out.height * 4) {
    throw Error("renderer: a " + std::to_string(width) + "x" + std::to_string(height) +
                " view does not fit at column " + std::to_string(x_offset_px) + " of a " +
                std::to_string(out.width) + "x" + std::to_string(out.height) + " image");
  }
}

void Renderer::renderInto(const Scene& scene, const CameraDef& camera_def, RgbaImage& out,
                          int x_offset_px) {
  checkFits(out, impl_->width, impl_->height, x_offset_px);
  const CurrentContext current(*impl_->context);
  impl_->drawWhole(scene, camera(scene, camera_def));
  impl_->readRgba(out.pixels.data() + static_cast<std::size_t>(x_offset_px) * 4, out.width);
}

void Renderer::Impl::readRows(std::uint8_t* dst, int row_length_px, int y0, int y1) {
  gl->PixelStorei(GL_PACK_ROW_LENGTH, row_length_px);
  gl->ReadPixels(0, y0, width, y1 - y0, GL_RGBA, GL_UNSIGNED_BYTE,
                 dst + static_cast<std::size_t>(y0) * static_cast<std::size_t>(row_length_px) * 4);
  gl->PixelStorei(GL_PACK_ROW_LENGTH, 0);
  checkGl(*gl, "render");
}

}  // namespace parksim
