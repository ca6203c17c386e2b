// libFuzzer harness for the sweep-spec reader (parseSweepSpec in
// parksim/sweep/spec/SweepSpecReader.h): any bytes must give a spec or a parksim::Error, never a
// crash, a sanitizer report, a hang or unbounded memory. World paths resolve against a scratch
// directory holding w.yaml and v.yaml. Built and run by scripts/fuzz.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/sweep/spec/SweepSpecReader.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string dir = [] {
    const std::string d = parksim::fuzz::scratchDir();
    parksim::fuzz::writeFile(d + "/w.yaml", "format: parksim-world/1\n");
    parksim::fuzz::writeFile(d + "/v.yaml", "format: parksim-world/1\n");
    return d;
  }();
  try {
    const parksim::SweepSpec spec = parksim::parseSweepSpec(
        std::string_view(reinterpret_cast<const char*>(data), size), "spec.yaml", dir);
    // What the reader promises: every axis has a value, offsets have their lines.
    if (spec.world_files.empty() || spec.world_files.size() != spec.world_paths.size()) {
      std::abort();
    }
    if (spec.planners.empty() || spec.controllers.empty() || spec.seeds.empty() ||
        spec.start_offsets.empty() || spec.start_offsets.size() != spec.start_offset_lines.size() ||
        spec.goal_offsets.size() != spec.goal_offset_lines.size()) {
      std::abort();
    }
  } catch (const parksim::Error&) {
  }
  return 0;
}
