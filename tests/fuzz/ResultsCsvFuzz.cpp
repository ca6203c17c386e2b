// libFuzzer harness for the results.csv reader (CsvFollower in
// parksim/results/tables/ResultsFile.h, through verifyResults in TableVerify.h, which `parksim
// verify` and a resumed sweep use): a valid results.jsonl beside a results.csv of any bytes must
// give a verdict listing problems, never a crash, a sanitizer report or a hang; results.csv as the
// writer renders it must pass. Built and run by scripts/fuzz.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/results/tables/ResultsFile.h"
#include "parksim/results/tables/TableVerify.h"
#include "parksim/sweep/shards/Merge.h"
#include "tests/fuzz/FuzzSupport.h"

namespace {

// Three rows, one of them with every kind of CSV cell (quotes, commas, lists, booleans).
const std::vector<nlohmann::ordered_json>& rows() {
  static const std::vector<nlohmann::ordered_json> r = [] {
    std::vector<nlohmann::ordered_json> v;
    for (int i = 0; i < 3; ++i) {
      nlohmann::ordered_json row;
      row["episode_id"] = "000000000000000" + std::to_string(i);
      row["world"] = "w";
      row["planner"] = "rrt";
      row["seed"] = i;
      row["met_tolerance"] = i != 1;
      row["failure"] = i == 1 ? "goal missed: \"far\", 3 mm" : "";
      row["contact_bodies"] = nlohmann::ordered_json::array({"a", "b,c"});
      row["max_pos_err_m"] = 0.001 * i;
      row["world_hash"] = "0123456789abcdef";
      row["parksim_version"] = "0.3.0";
      v.push_back(row);
    }
    return v;
  }();
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& dir = parksim::fuzz::scratchDir();
  static const bool written = [&dir] {
    parksim::writeResultsTable(dir, rows());
    return true;
  }();
  (void)written;
  static const std::string good_csv = [&dir] {
    std::FILE* f = std::fopen((dir + "/results.csv").c_str(), "rb");
    std::string text;
    char buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
    std::fclose(f);
    return text;
  }();
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  parksim::fuzz::writeFile(dir + "/results.csv", bytes);
  try {
    const parksim::TableVerification v = parksim::verifyResults(dir);
    if (v.rows != rows().size()) std::abort();  // results.jsonl is whole
    if (bytes == good_csv && !v.ok()) std::abort();
    // A results.csv that ends early by at most one row is a note, anything else differing a
    // problem: a prefix of the good file is never reported as differing.
  } catch (const parksim::Error&) {
    std::abort();  // a directory with results.jsonl always gets a verdict
  }
  return 0;
}
