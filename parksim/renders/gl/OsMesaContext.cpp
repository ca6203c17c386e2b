#include "parksim/renders/gl/OsMesaContext.h"

// First: <GL/osmesa.h> includes <GL/gl.h>, which would hide glcorearb.h's GL 1.1 types.
#include "parksim/renders/gl/GlFunctions.h"

#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <GL/osmesa.h>

#include <array>
#include <optional>
#include <string>

#include "parksim/core/io/Error.h"
#include "parksim/core/system/SharedLibrary.h"

namespace parksim::detail {

namespace {

// libOSMesa, loaded when the first OSMesa context is made: it brings LLVM and a dozen more
// libraries that a process which never renders should not map. Typed by <GL/osmesa.h>'s
// declarations, which are never called directly (nothing links libOSMesa).
struct OsMesaApi {
  SharedLibrary library{PARKSIM_OSMESA_LIBRARY, "OSMesa", "install the Debian package libosmesa6"};
  decltype(&::OSMesaCreateContextAttribs) CreateContextAttribs =
      library.function<decltype(&::OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
  decltype(&::OSMesaDestroyContext) DestroyContext =
      library.function<decltype(&::OSMesaDestroyContext)>("OSMesaDestroyContext");
  decltype(&::OSMesaGetCurrentContext) GetCurrentContext =
      library.function<decltype(&::OSMesaGetCurrentContext)>("OSMesaGetCurrentContext");
  decltype(&::OSMesaGetProcAddress) GetProcAddress =
      library.function<decltype(&::OSMesaGetProcAddress)>("OSMesaGetProcAddress");
  decltype(&::OSMesaMakeCurrent) MakeCurrent =
      library.function<decltype(&::OSMesaMakeCurrent)>("OSMesaMakeCurrent");
};

// What OSMesa needs of EGL: releasing an EGL context current on this thread. Only when the
// process has loaded libEGL (an EGL context was made): otherwise there is none to release.
struct EglRelease {
  SharedLibrary library;
  PFNEGLGETCURRENTCONTEXTPROC GetCurrentContext =
      library.function<PFNEGLGETCURRENTCONTEXTPROC>("eglGetCurrentContext");
  PFNEGLGETCURRENTDISPLAYPROC GetCurrentDisplay =
      library.function<PFNEGLGETCURRENTDISPLAYPROC>("eglGetCurrentDisplay");
  PFNEGLMAKECURRENTPROC MakeCurrent = library.function<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");

  void releaseCurrent() const {
    if (GetCurrentContext() != EGL_NO_CONTEXT) {
      MakeCurrent(GetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
  }
};

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
    ctx_ = osmesa_.CreateContextAttribs(attribs.data(), nullptr);
    if (ctx_ == nullptr) {
      throw EnvironmentError("OSMesa: cannot create an OpenGL " + std::to_string(def.gl_major) +
                             "." + std::to_string(def.gl_minor) + " core context");
    }
    try {
      makeCurrent();
      setGlFunctions(loadGlFunctions(osmesa_.GetProcAddress, "OSMesa"));
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
    // libEGL may arrive after this context was made: it is looked for until it is there.
    if (!egl_) {
      if (std::optional<SharedLibrary> lib = SharedLibrary::ifLoaded(PARKSIM_EGL_LIBRARY)) {
        egl_.emplace(EglRelease{std::move(*lib)});
      }
    }
    if (egl_) egl_->releaseCurrent();
    // Drawing goes to the caller's framebuffer objects; the window-system buffer OSMesa
    // insists on is a single pixel.
    if (!osmesa_.MakeCurrent(ctx_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw EnvironmentError("OSMesa: cannot make the context current");
    }
  }

  bool isCurrent() const override { return osmesa_.GetCurrentContext() == ctx_; }

  void releaseCurrent() override {
    if (isCurrent()) osmesa_.MakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }

  std::string description() const override { return description_; }

  ContextBackend backend() const override { return ContextBackend::kOsMesa; }

 private:
  void release() {
    releaseCurrent();
    osmesa_.DestroyContext(ctx_);
  }

  OsMesaApi osmesa_;
  std::optional<EglRelease> egl_;
  OSMesaContext ctx_ = nullptr;
  std::array<unsigned char, 4> pixel_{};
  std::string description_;
};

}  // namespace

std::unique_ptr<OffscreenContext> createOsMesaContext(const ContextDef& def) {
  return std::make_unique<OsMesaContext>(def);
}

}  // namespace parksim::detail
