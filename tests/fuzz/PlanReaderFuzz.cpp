// libFuzzer harness for the plan-file reader (parseTrajectoryCsv in
// parksim/results/episode/TrajectoryFile.h): any bytes must give a Trajectory within PlanFileLimits
// or a parksim::Error. Built and run by scripts/fuzz.sh (docs/limits.md explains the campaigns).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/results/episode/TrajectoryFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using L = parksim::PlanFileLimits;
  try {
    const parksim::Trajectory t = parksim::parseTrajectoryCsv(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
    // What the reader promises about an accepted plan.
    if (t.points.empty() || t.points.size() > L::kMaxRows) std::abort();
    for (std::size_t i = 0; i < t.points.size(); ++i) {
      const double ts = t.points[i].t_s;
      if (!(ts >= 0.0 && ts <= L::kMaxTimeS)) std::abort();
      if (i > 0 && !(ts > t.points[i - 1].t_s && ts - t.points[i - 1].t_s <= L::kMaxGapS)) {
        std::abort();
      }
    }
  } catch (const parksim::Error&) {
  }
  return 0;
}
