#include "parksim/renders/gl/OffscreenContext.h"

#include <cstdlib>

#include "parksim/core/io/Error.h"
#include "parksim/renders/gl/EglContext.h"
#include "parksim/renders/gl/GlFunctions.h"
#include "parksim/renders/gl/OsMesaContext.h"

namespace parksim {

const char* toString(ContextBackend backend) {
  switch (backend) {
    case ContextBackend::kAuto: return "auto";
    case ContextBackend::kEgl: return "egl";
    case ContextBackend::kOsMesa: return "osmesa";
  }
  return "?";
}

ContextBackend contextBackendFromString(const std::string& name) {
  for (ContextBackend b : {ContextBackend::kAuto, ContextBackend::kEgl, ContextBackend::kOsMesa}) {
    if (name == toString(b)) return b;
  }
  throw Error("unknown OpenGL backend '" + name + "' (auto, egl or osmesa)");
}

bool contextBackendBuilt(ContextBackend backend) {
#ifdef PARKSIM_HAVE_OSMESA
  (void)backend;
  return true;
#else
  return backend != ContextBackend::kOsMesa;
#endif
}

ContextBackend effectiveContextBackend(ContextBackend requested) {
  if (requested != ContextBackend::kAuto) return requested;
  const char* env = std::getenv("PARKSIM_GL_BACKEND");
  if (env == nullptr || *env == '\0') return requested;
  try {
    return contextBackendFromString(env);
  } catch (const Error& e) {
    throw Error(std::string("PARKSIM_GL_BACKEND: ") + e.what());
  }
}

OffscreenContext::OffscreenContext() = default;
OffscreenContext::~OffscreenContext() = default;

const GlFunctions& OffscreenContext::gl() const {
  if (!gl_) throw Error("offscreen context: the backend loaded no GL functions");
  return *gl_;
}

void OffscreenContext::setGlFunctions(const GlFunctions& gl) {
  gl_ = std::make_unique<GlFunctions>(gl);
}

namespace {

std::unique_ptr<OffscreenContext> createOsMesa(const ContextDef& def) {
#ifdef PARKSIM_HAVE_OSMESA
  return detail::createOsMesaContext(def);
#else
  (void)def;
  throw Error("OSMesa: this parksim was built without OSMesa (Mesa 25.1 and later have none)");
#endif
}

std::unique_ptr<OffscreenContext> create(ContextBackend backend, const ContextDef& def) {
  switch (backend) {
    case ContextBackend::kEgl: return detail::createEglContext(def);
    case ContextBackend::kOsMesa: return createOsMesa(def);
    case ContextBackend::kAuto: break;
  }
  // Software contexts: EGL first (the one current Mesa has), OSMesa where EGL cannot.
  try {
    return detail::createEglContext(def);
  } catch (const Error& egl) {
    try {
      return createOsMesa(def);
    } catch (const Error& osmesa) {
      throw EnvironmentError(std::string("no OpenGL context: ") + egl.what() + "; " +
                             osmesa.what());
    }
  }
}

}  // namespace

std::unique_ptr<OffscreenContext> createOffscreenContext(const ContextDef& def) {
  return create(effectiveContextBackend(def.backend), def);
}

}  // namespace parksim
