// parksim verify DIR: checks a sweep's results tables (DIR's and, for a Slurm sweep, each
// DIR/shards/*) without changing them, and lists every problem with its file and line: rows
// whose seal does not match their content (changed bytes), lines that are not rows, lines of
// results.csv that are not the rendering of their results.jsonl row, an episode twice, rows of
// other world contents or parksim builds (parksim/results/tables/TableVerify.h).
// Exit status: 0 when every table is whole, 1 when problems were found, 2 on bad input.

#include <cstdio>
#include <memory>
#include <string>

#include "app/Command.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/sweep/shards/Merge.h"

namespace parksim::app {

using cli::printable;

namespace {

int runVerify(const std::string& dir) {
  const TableVerification v = verifyResults(dir);
  for (const std::string& p : v.problems) std::fprintf(stderr, "%s\n", printable(p).c_str());
  if (v.unlisted > 0) std::fprintf(stderr, "... and %zu more problems\n", v.unlisted);
  for (const std::string& n : v.notes) std::fprintf(stderr, "note: %s\n", printable(n).c_str());
  const std::size_t problems = v.problems.size() + v.unlisted;
  std::printf("verified %zu table%s in %s: %zu rows intact, %zu problem%s\n", v.tables.size(),
              v.tables.size() == 1 ? "" : "s", printable(dir).c_str(), v.rows, problems,
              problems == 1 ? "" : "s");
  return v.ok() ? kExitOk : 1;
}

}  // namespace

CommandRunner setupVerifyCommand(CLI::App& sub) {
  auto dir = std::make_shared<std::string>();
  sub.add_option("dir", *dir, "a sweep's output directory (results.jsonl, results.csv, shards/)")
      ->required();
  return [dir](const OutputOptions&) { return runVerify(*dir); };
}

}  // namespace parksim::app
