#include "parksim/renders/OsMesaContext.h"

// First: <GL/osmesa.h> includes <GL/gl.h>, which would hide glcorearb.h's GL 1.1 types.
#include "parksim/renders/GlFunctions.h"

#include <EGL/egl.h>
#include <GL/osmesa.h>

#include <array>
#include <string>

#include "parksim/core/Error.h"

namespace parksim::detail {

namespace {

class OsMesaContext final : public OffscreenContext {
 public:
  explicit OsMesaContext(const ContextDef& def) {
    const std::array<int, 11> attribs = {OSMESA_FORMAT,
                                         OSMESA_RGBA,
                                         OSMESA_DEPTH_BITS,
                                         0,
                                         OSMESA_PROFILE,
                                         OSMESA_CORE_PROFILE,
                                         OSMESA_CONTEXT_MAJOR_VERSION,
                                         def.gl_major,
                                         OSMESA_CONTEXT_MINOR_VERSION,
                                         def.gl_minor,
                                         0};
    ctx_ = OSMesaCreateContextAttribs(attribs.data(), nullptr);
    if (ctx_ == nullptr) {
      throw EnvironmentError("OSMesa: cannot create an OpenGL " + std::to_string(def.gl_major) +
                             "." + std::to_string(def.gl_minor) + " core context");
    }
    try {
      makeCurrent();
      setGlFunctions(loadGlFunctions(&OSMesaGetProcAddress, "OSMesa"));
      description_ = "OSMesa: " + glVersionAndRenderer(gl());
    } catch (...) {
      release();
      throw;
    }
  }

  ~OsMesaContext() override { release(); }

  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void makeCurrent() override {
    // Mesa's EGL and OSMesa share one GL dispatch (libglapi) but keep separate books of what is
    // current: an EGL context left current would go on believing it is, and its calls would
    // reach this context. It is released first (afterwards, releasing it would unbind this one).
    if (eglGetCurrentContext() != EGL_NO_CONTEXT) {
      eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    // Drawing goes to the caller's framebuffer objects; the window-system buffer OSMesa
    // insists on is a single pixel.
    if (!OSMesaMakeCurrent(ctx_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw EnvironmentError("OSMesa: cannot make the context current");
    }
  }

  bool isCurrent() const override { return OSMesaGetCurrentContext() == ctx_; }

  void releaseCurrent() override {
    if (isCurrent()) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }

  std::string description() const override { return description_; }

  ContextBackend backend() const override { return ContextBackend::kOsMesa; }

 private:
  void release() {
    releaseCurrent();
    OSMesaDestroyContext(ctx_);
  }

  OSMesaContext ctx_ = nullptr;
  std::array<unsigned char, 4> pixel_{};
  std::string description_;
};

}  // namespace

std::unique_ptr<OffscreenContext> createOsMesaContext(const ContextDef& def) {
  return std::make_unique<OsMesaContext>(def);
}

}  // namespace parksim::detail
