#include "parksim/cli/GlBackendOption.h"

#include "parksim/core/io/Error.h"

namespace parksim::cli {

void GlBackendOption::addTo(CLI::App& sub) {
  sub.add_option("--gl-backend", name,
                 "OpenGL backend: egl (surfaceless, Mesa's software device), osmesa, or auto "
                 "(PARKSIM_GL_BACKEND if set, else egl, then osmesa)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
}

ContextDef GlBackendOption::context() const {
  ContextDef def;
  def.backend = contextBackendFromString(name);
  const ContextBackend effective = effectiveContextBackend(def.backend);
  if (!contextBackendBuilt(effective)) {
    throw Error(std::string(def.backend == effective ? "--gl-backend " : "PARKSIM_GL_BACKEND=") +
                toString(effective) + ": this parksim was built without OSMesa");
  }
  return def;
}

}  // namespace parksim::cli
