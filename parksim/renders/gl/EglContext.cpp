#include "parksim/renders/gl/EglContext.h"

// No prototypes: every EGL function is called through the library loaded at run time (EglApi),
// so a direct eglFoo() call does not compile.
#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <array>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/core/system/SharedLibrary.h"
#include "parksim/renders/gl/GlFunctions.h"

namespace parksim::detail {

namespace {

// X(Name, NAME): eglName, typed by <EGL/egl.h>'s PFNEGLNAMEPROC. Exactly the functions used here.
#define PARKSIM_EGL_FUNCTIONS(X)            \
  X(BindAPI, BINDAPI)                       \
  X(CreateContext, CREATECONTEXT)           \
  X(DestroyContext, DESTROYCONTEXT)         \
  X(GetCurrentContext, GETCURRENTCONTEXT)   \
  X(GetError, GETERROR)                     \
  X(GetPlatformDisplay, GETPLATFORMDISPLAY) \
  X(GetProcAddress, GETPROCADDRESS)         \
  X(Initialize, INITIALIZE)                 \
  X(MakeCurrent, MAKECURRENT)               \
  X(QueryAPI, QUERYAPI)                     \
  X(QueryString, QUERYSTRING)

// libEGL (glvnd's), loaded when the first EGL context is made: a process that never renders
// does not map it, nor Mesa behind it.
struct EglApi {
  SharedLibrary library{PARKSIM_EGL_LIBRARY, "EGL",
                        "install the Debian packages libegl1 and libegl-mesa0"};
#define PARKSIM_EGL_MEMBER(name, NAME) \
  PFNEGL##NAME##PROC name = library.function<PFNEGL##NAME##PROC>("egl" #name);
  PARKSIM_EGL_FUNCTIONS(PARKSIM_EGL_MEMBER)
#undef PARKSIM_EGL_MEMBER
};

const char* eglErrorName(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT: return "EGL_BAD_DEVICE_EXT";
    default: break;
  }
  return "unknown EGL error";
}

/// "EGL: WHAT (EGL_BAD_MATCH, 0x3009)", with the calling thread's last EGL error.
EnvironmentError eglFailure(const EglApi& egl, const std::string& what) {
  const EGLint code = egl.GetError();
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", static_cast<unsigned>(code));
  return EnvironmentError("EGL: " + what + " (" + eglErrorName(code) + ", " + hex + ")");
}

/// Whether the space-separated extension list `list` (may be null) holds `name`.
bool hasExtension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  const std::string_view all(list);
  for (std::size_t pos = 0; pos < all.size();) {
    const std::size_t end = std::min(all.find(' ', pos), all.size());
    if (all.substr(pos, end - pos) == name) return true;
    pos = end + 1;
  }
  return false;
}

struct Display {
  EGLDisplay display = EGL_NO_DISPLAY;
  const char* kind = "";  // for the description
};

// Mesa's software device when EGL lists it: llvmpipe, whatever GPUs the machine has, so images
// do not depend on the machine. Else Mesa's surfaceless platform (which may pick a GPU).
Display openDisplay(const EglApi& egl) {
  const char* client = egl.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (hasExtension(client, "EGL_EXT_device_enumeration") &&
      hasExtension(client, "EGL_EXT_platform_device")) {
    const auto query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl.GetProcAddress("eglQueryDevicesEXT"));
    const auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        egl.GetProcAddress("eglQueryDeviceStringEXT"));
    EGLint count = 0;
    if (query_devices != nullptr && query_string != nullptr && query_devices(0, nullptr, &count) &&
        count > 0) {
      std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
      if (query_devices(count, devices.data(), &count)) {
        devices.resize(static_cast<std::size_t>(count));
        for (EGLDeviceEXT device : devices) {
          if (!hasExtension(query_string(device, EGL_EXTENSIONS), "EGL_MESA_device_software")) {
            continue;
          }
          const EGLDisplay d = egl.GetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
          if (d != EGL_NO_DISPLAY) return {d, "device: software"};
        }
      }
    }
  }
  if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    const EGLDisplay d =
        egl.GetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) return {d, "surfaceless"};
  }
  throw EnvironmentError(
      std::string("EGL: neither Mesa's software device nor its surfaceless platform is "
                  "available (client extensions: ") +
      (client != nullptr && *client != '\0' ? client : "none") + ")");
}

class EglContext final : public OffscreenContext {
 public:
  explicit EglContext(const ContextDef& def) {
    const Display d = openDisplay(egl_);
    display_ = d.display;
    // A display is shared by the whole process (eglGetPlatformDisplay returns the same handle
    // for the same device), and eglTerminate would end every context on it, other renderers'
    // included: displays stay initialized until Mesa releases them at exit. Initializing an
    // initialized display does nothing.
    EGLint major = 0;
    EGLint minor = 0;
    if (!egl_.Initialize(display_, &major, &minor)) {
      throw eglFailure(egl_, "cannot initialize the display");
    }
    if (major < 1 || (major == 1 && minor < 5)) {
      throw EnvironmentError("EGL: version " + std::to_string(major) + "." + std::to_string(minor) +
                             ", 1.5 is needed");
    }
    const char* extensions = egl_.QueryString(display_, EGL_EXTENSIONS);
    for (const char* needed : {"EGL_KHR_surfaceless_context", "EGL_KHR_no_config_context"}) {
      if (!hasExtension(extensions, needed)) {
        throw EnvironmentError(std::string("EGL: the display lacks ") + needed);
      }
    }
    if (!egl_.BindAPI(EGL_OPENGL_API)) throw eglFailure(egl_, "no desktop OpenGL");
    const std::array<EGLint, 7> attribs = {EGL_CONTEXT_MAJOR_VERSION,
                                           def.gl_major,
                                           EGL_CONTEXT_MINOR_VERSION,
                                           def.gl_minor,
                                           EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                           EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                           EGL_NONE};
    ctx_ = egl_.CreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs.data());
    if (ctx_ == EGL_NO_CONTEXT) {
      throw eglFailure(egl_, "cannot create an OpenGL " + std::to_string(def.gl_major) + "." +
                                 std::to_string(def.gl_minor) + " core context");
    }
    try {
      makeCurrent();
      setGlFunctions(loadGlFunctions(egl_.GetProcAddress, "EGL"));
      description_ = std::string("EGL (") + d.kind + "): " + glVersionAndRenderer(gl());
    } catch (...) {
      release();
      throw;
    }
  }

  ~EglContext() override { release(); }

  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void makeCurrent() override {
    // The bound API is per thread, and the current context EGL reports is the one of that API.
    if (!egl_.BindAPI(EGL_OPENGL_API)) throw eglFailure(egl_, "no desktop OpenGL");
    if (!egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_)) {
      throw eglFailure(egl_, "cannot make the context current");
    }
  }

  bool isCurrent() const override {
    return egl_.QueryAPI() == EGL_OPENGL_API && egl_.GetCurrentContext() == ctx_;
  }

  void releaseCurrent() override {
    if (isCurrent()) egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }

  std::string description() const override { return description_; }

  ContextBackend backend() const override { return ContextBackend::kEgl; }

 private:
  void release() {
    releaseCurrent();
    egl_.DestroyContext(display_, ctx_);
  }

  EglApi egl_;  // first: loaded before anything else is done
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext ctx_ = EGL_NO_CONTEXT;
  std::string description_;
};

}  // namespace

std::unique_ptr<OffscreenContext> createEglContext(const ContextDef& def) {
  return std::make_unique<EglContext>(def);
}

}  // namespace parksim::detail
