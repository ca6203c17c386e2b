#pragma once
// An OpenGL context without a window. Callers draw into their own framebuffer objects, so a
// context needs no default framebuffer: that keeps backends interchangeable. OSMesa is the one
// backend today; it was removed from Mesa 25.1, and an EGL surfaceless backend (same contract:
// make current, then FBOs) would be added here as another ContextBackend without touching any
// caller.

#include <memory>
#include <string>

namespace parksim {

enum class ContextBackend {
  kOsMesa,  ///< Mesa's off-screen library (llvmpipe, software), Mesa <= 25.0
};

struct ContextDef {
  ContextBackend backend = ContextBackend::kOsMesa;
  int gl_major = 3;  ///< core profile version asked for; the context may be newer
  int gl_minor = 3;
};

class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;

  /// Makes the context current on the calling thread. Throws Error on failure.
  virtual void makeCurrent() = 0;
  /// True when the context is current on the calling thread.
  virtual bool isCurrent() const = 0;
  /// Backend, GL version and renderer, e.g. "OSMesa: 4.5 (Core Profile) Mesa 22.3.6, llvmpipe".
  virtual std::string description() const = 0;
};

/// Creates a context of the requested backend and makes it current on the calling thread.
/// Throws Error with the backend's reason when it cannot.
std::unique_ptr<OffscreenContext> createOffscreenContext(const ContextDef& def = {});

}  // namespace parksim
