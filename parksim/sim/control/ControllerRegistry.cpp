// parksim's own controllers. A new built-in controller: its file, and a line here.

#include "parksim/sim/control/Controller.h"
#include "parksim/sim/control/TrackingController.h"

namespace parksim {

const ControllerRegistry& builtInControllers() {
  static const ControllerRegistry registry = [] {
    ControllerRegistry r;
    r.add(trackingControllerEntry());
    return r;
  }();
  return registry;
}

}  // namespace parksim
