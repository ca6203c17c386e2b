// libFuzzer harness for the world-file reader (parksim/scenario/world/ScenarioReader.h): any bytes
// must give a Scenario or a parksim::Error, never a crash, a sanitizer report, a hang or
// unbounded memory. Built and run by scripts/fuzz.sh (docs/limits.md explains the campaigns).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/ScenarioReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)parksim::parseScenario(std::string_view(reinterpret_cast<const char*>(data), size),
                                 "fuzz.yaml");
  } catch (const parksim::Error&) {
    // bad input, reported: the expected outcome for most inputs
  }
  return 0;
}
