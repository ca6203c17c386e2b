// libFuzzer harness for the C++ half of Python's dict-to-world path (parksim.load_world(dict):
// json.dumps(dict, indent=1) -> parseWorld, python/parksim/__init__.py): the input is read as
// JSON, written back as Python's json.dumps writes it (indent 1, ASCII escapes; NaN and
// Infinity as Python spells them, and integers of any size), and read as a world. Any value
// must give a World or a parksim::Error, never a crash, a sanitizer report or a hang. Built and
// run by scripts/fuzz.sh; tests/fuzz/world_dict_fuzz.py drives the Python half.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/World.h"

namespace {

// Python's json.dumps spells non-finite floats NaN, Infinity and -Infinity (allow_nan=True).
// The fuzzer's bytes choose where they go: "NaN", "Infinity" strings become those words.
std::string pythonSpelling(std::string text) {
  for (const char* word : {"NaN", "Infinity", "-Infinity"}) {
    const std::string quoted = std::string("\"") + word + "\"";
    for (std::size_t at = text.find(quoted); at != std::string::npos; at = text.find(quoted, at)) {
      text.replace(at, quoted.size(), word);
    }
  }
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const nlohmann::json dict = nlohmann::json::parse(bytes, nullptr, false);
  if (dict.is_discarded()) return 0;
  std::string text;
  try {
    text = pythonSpelling(dict.dump(1, ' ', true));
  } catch (const nlohmann::json::exception&) {
    return 0;  // not text Python's json module would make (invalid UTF-8)
  }
  try {
    (void)parksim::parseWorld(text, "<dict>");
  } catch (const parksim::Error&) {
  }
  return 0;
}
