#pragma once
// An OpenGL context without a window. Callers draw into their own framebuffer objects, so a
// context needs no default framebuffer: that keeps backends interchangeable.
//
// Backends: EGL without a surface (EGL_KHR_surfaceless_context) on Mesa's software device,
// llvmpipe, and OSMesa, Mesa's older off-screen library (removed from Mesa 25.1, so optional at
// build time). Both draw with llvmpipe and give byte-identical images. Each context carries its
// backend's GL entry points (gl()), loaded through that backend's get-proc-address, so both
// backends can live in one process.

#include <memory>
#include <string>

namespace parksim {

struct GlFunctions;  // internal to parksim_render (GlFunctions.h)

enum class ContextBackend {
  /// PARKSIM_GL_BACKEND when it is set (egl, osmesa or auto), else EGL, and OSMesa when EGL
  /// cannot make a context.
  kAuto,
  kEgl,     ///< EGL 1.5, surfaceless, on Mesa's software device (llvmpipe)
  kOsMesa,  ///< Mesa's off-screen library (llvmpipe), Mesa <= 25.0
};

/// "auto", "egl", "osmesa".
const char* toString(ContextBackend backend);
/// Parses "auto", "egl" or "osmesa"; throws Error naming the accepted names otherwise.
ContextBackend contextBackendFromString(const std::string& name);
/// Whether this build has the backend (OSMesa is optional; EGL and auto always are).
bool contextBackendBuilt(ContextBackend backend);
/// The backend createOffscreenContext takes for `requested`: `requested` itself unless it is
/// kAuto, else PARKSIM_GL_BACKEND's (which may be kAuto again: EGL, then OSMesa). Throws Error
/// naming the variable when its value is not a backend name.
ContextBackend effectiveContextBackend(ContextBackend requested);

struct ContextDef {
  ContextBackend backend = ContextBackend::kAuto;
  int gl_major = 3;  ///< core profile version asked for; the context may be newer
  int gl_minor = 3;
};

class OffscreenContext {
 public:
  virtual ~OffscreenContext();

  /// Makes the context current on the calling thread. Throws Error on failure.
  virtual void makeCurrent() = 0;
  /// True when the context is current on the calling thread.
  virtual bool isCurrent() const = 0;
  /// Leaves the calling thread without a current context when this one is current, so that
  /// another thread may make it current (EGL refuses a context current elsewhere).
  virtual void releaseCurrent() = 0;
  /// Backend, GL version and renderer, e.g. "EGL (device: software): 4.5 (Core Profile) Mesa
  /// 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)".
  virtual std::string description() const = 0;
  /// The backend that made the context (never kAuto).
  virtual ContextBackend backend() const = 0;

  /// This context's GL entry points; call them only while it is current.
  const GlFunctions& gl() const;

 protected:
  OffscreenContext();
  /// Backends store their loaded entry points once, in their constructor.
  void setGlFunctions(const GlFunctions& gl);

 private:
  std::unique_ptr<GlFunctions> gl_;
};

/// Creates a context of the requested backend and makes it current on the calling thread.
/// kAuto reads PARKSIM_GL_BACKEND (an explicit backend in `def` wins over it). Throws
/// EnvironmentError with the backend's reason when it cannot make one (with kAuto and neither
/// working: both reasons), Error for a bad PARKSIM_GL_BACKEND or a backend not built.
std::unique_ptr<OffscreenContext> createOffscreenContext(const ContextDef& def = {});

}  // namespace parksim
