#include "parksim/sim/episode/ExecutionDef.h"

#include "parksim/core/io/Error.h"

namespace parksim {

const char* toString(TrackingMode mode) { return mode == TrackingMode::kOpen ? "open" : "closed"; }

TrackingMode trackingModeFromString(const std::string& name) {
  if (name == "open") return TrackingMode::kOpen;
  if (name == "closed") return TrackingMode::kClosed;
  throw Error("unknown tracking mode '" + name + "' (expected closed or open)");
}

}  // namespace parksim
