// libFuzzer harness for the results.jsonl reader (scanResultsJsonl in
// parksim/results/tables/ResultsFile.h, which sweep, merge, report and verify use): any bytes must
// give checked rows or a parksim::Error naming a line, never a crash, a sanitizer report or a hang.
// The rows it accepts are rendered as the writer would (CSV, origins), and a scan that goes on
// past problems (verify's) must see the same rows. Built and run by scripts/fuzz.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/results/tables/ResultsFile.h"
#include "parksim/results/tables/RowSeal.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const parksim::fuzz::MemFile file(bytes);
  std::size_t strict_rows = 0;
  bool strict_ok = true;
  try {
    parksim::TableOrigins origins;
    parksim::scanResultsJsonl(file.path(), [&](const parksim::TableRow& r) {
      // An accepted row is sealed, and renders as a CSV line ending in its checksum.
      if (parksim::sealProblem(r.text)) std::abort();
      std::set<std::string, std::less<>> set_keys;
      parksim::addSetKeys(r.row, set_keys);
      const std::string csv =
          parksim::csvRow(r.row, parksim::resultColumns({set_keys.begin(), set_keys.end()}));
      if (csv.empty() || csv.back() != '\n') std::abort();
      origins.add(r.row, file.path(), r.line);
      ++strict_rows;
    });
    (void)origins.mixes();
  } catch (const parksim::Error&) {
    strict_ok = false;
  }
  // Going on past problems: never fewer rows, and as many when nothing was wrong.
  std::size_t lenient_rows = 0;
  std::size_t problems = 0;
  try {
    parksim::scanResultsJsonl(
        file.path(), [&](const parksim::TableRow&) { ++lenient_rows; },
        [&](std::size_t, const std::string&) { ++problems; });
  } catch (const parksim::Error&) {
    // only the file itself (type, size) may stop this scan
  }
  if (lenient_rows < strict_rows) std::abort();
  if (strict_ok && (problems != 0 || lenient_rows != strict_rows)) std::abort();
  return 0;
}
