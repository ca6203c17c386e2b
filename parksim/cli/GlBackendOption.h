#pragma once
// `--gl-backend auto|egl|osmesa` on the commands that render (run with frames, render). Without
// it, or with auto, PARKSIM_GL_BACKEND chooses; without that, EGL, then OSMesa when EGL cannot
// make a context (docs/rendering.md).

#include <string>

#include <CLI/CLI.hpp>

#include "parksim/renders/gl/OffscreenContext.h"

namespace parksim::cli {

struct GlBackendOption {
  std::string name = "auto";

  /// Registers --gl-backend on `sub`.
  void addTo(CLI::App& sub);
  /// The context definition asked for, checked now (before anything is written): throws Error
  /// when PARKSIM_GL_BACKEND is not a backend name or the backend is not in this build.
  ContextDef context() const;
};

}  // namespace parksim::cli
