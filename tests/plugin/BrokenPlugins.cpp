// Shared libraries that are not plugins parksim can load, one per way of being wrong; built
// several times with BROKEN_KIND set (CMakeLists.txt): the loader must refuse each in one line.

#include <csignal>
#include <cstdint>
#include <cstdlib>

#include <unistd.h>

#include "parksim/usercode/PluginApi.h"

namespace {

void registerNothing(parksim::PluginRegistrar&) {}

void registerTakenName(parksim::PluginRegistrar& r) {
  // "tracking" is parksim's own controller.
  parksim::ControllerInfo info;
  info.name = "tracking";
  r.addController({info, [](const parksim::ParamMap&) -> std::unique_ptr<parksim::Controller> {
                     return nullptr;
                   }});
}

}  // namespace

#if BROKEN_KIND == 1  // built against another plugin API version
extern "C" __attribute__((visibility("default"))) const parksim::PluginDescriptor*
parksim_plugin() {
  static const parksim::PluginDescriptor d{PARKSIM_PLUGIN_API_VERSION + 1,
                                           parksim::pluginAbiFingerprint(), "future", "9",
                                           registerNothing};
  return &d;
}
#elif BROKEN_KIND == 2  // built against headers with other type layouts
extern "C" __attribute__((visibility("default"))) const parksim::PluginDescriptor*
parksim_plugin() {
  static const parksim::PluginDescriptor d{PARKSIM_PLUGIN_API_VERSION, 0x1234, "other-abi", "1",
                                           registerNothing};
  return &d;
}
#elif BROKEN_KIND == 3  // registers nothing
PARKSIM_PLUGIN("empty", "1", registerNothing)
#elif BROKEN_KIND == 4  // registers a name parksim already has
PARKSIM_PLUGIN("taken", "1", registerTakenName)
#elif BROKEN_KIND == 5  // its static initializer dies of a segmentation fault while it is loaded
namespace {
const int crash = std::raise(SIGSEGV);
}
PARKSIM_PLUGIN("crashing", "1", registerNothing)
#elif BROKEN_KIND == 6  // its static initializer aborts while it is loaded
namespace {
const int abort_at_load = (std::abort(), 0);
}
PARKSIM_PLUGIN("aborting", "1", registerNothing)
#elif BROKEN_KIND == 7  // its static initializer never returns while it is loaded
namespace {
int waitForever() {
  for (;;) ::pause();
}
const int hang = waitForever();
}  // namespace
PARKSIM_PLUGIN("hanging", "1", registerNothing)
#else                   // no entry point at all
extern "C" __attribute__((visibility("default"))) int not_a_parksim_plugin() { return 0; }
#endif
