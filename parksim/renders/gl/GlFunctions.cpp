#include "parksim/renders/gl/GlFunctions.h"

#include "parksim/core/io/Error.h"

namespace parksim {

GlFunctions loadGlFunctions(GlProcLoader load, const std::string& backend) {
  GlFunctions gl;
  // Function pointer to function pointer: reinterpret_cast is the defined conversion, and the
  // backend's loader promises the type glcorearb.h gives.
#define PARKSIM_GL_LOAD(name, NAME)                                                   \
  gl.name = reinterpret_cast<PFNGL##NAME##PROC>(load("gl" #name));                    \
  if (gl.name == nullptr) {                                                           \
    throw EnvironmentError(backend + ": the OpenGL library does not provide gl" #name \
                                     " (the renderer needs OpenGL 3.3 core)");        \
  }
  PARKSIM_GL_FUNCTIONS(PARKSIM_GL_LOAD)
#undef PARKSIM_GL_LOAD
  return gl;
}

std::string glVersionAndRenderer(const GlFunctions& gl) {
  auto str = [&gl](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(gl.GetString(name));
    return std::string(s != nullptr ? s : "?");
  };
  return str(GL_VERSION) + ", " + str(GL_RENDERER);
}

}  // namespace parksim
