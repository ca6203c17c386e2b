#pragma once
// parksim's OMPL plugin (OmplApi.h), loaded when first needed. It is looked up by name, as
// the dynamic loader looks up libraries: through the run path of the program or library that
// loads it (the build tree's lib/parksim/; installed, <prefix>/lib/parksim/, or beside the
// Python module), then LD_LIBRARY_PATH. Loading an already loaded plugin costs a lookup only.

#include "parksim/core/system/SharedLibrary.h"
#include "parksim/planner/steering/OmplApi.h"

namespace parksim {

class OmplPlugin {
 public:
  /// The file the plugin is built and installed as.
  static constexpr const char* kFileName = "libparksim_ompl_plugin.so";

  /// Loads the plugin. Throws EnvironmentError naming the file and the loader's reason when it
  /// cannot.
  OmplPlugin();

  const ParksimOmplApi& api() const { return *api_; }

 private:
  SharedLibrary library_;
  const ParksimOmplApi* api_;
};

}  // namespace parksim
