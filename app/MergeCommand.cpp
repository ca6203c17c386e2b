// parksim merge SRC... [--out DIR]: merges sweep output directories (shards, machines, runs)
// into one results table, each episode once, sorted by episode id; idempotent. `parksim merge
// DIR` merges DIR/shards/* (a Slurm sweep) into DIR. Lists the episodes that are missing (from
// the sweeps' manifests), duplicated or conflicting. Every row's seal is checked: a changed row
// stops the merge (exit 2, naming its file and line), and so do sources that mix world contents
// or builds, unless --allow-mixed. Exit status: 0 when the table is complete and without
// conflicts, 1 otherwise, 2 on bad input.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/Command.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/core/io/Error.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/shards/Merge.h"

namespace parksim::app {

using cli::printable;
using cli::printableLines;
namespace {

namespace fs = std::filesystem;

void list(const char* what, const std::vector<std::string>& ids) {
  if (ids.empty()) return;
  std::fprintf(stderr, "%zu %s:", ids.size(), what);
  for (std::size_t i = 0; i < ids.size() && i < 20; ++i)
    std::fprintf(stderr, " %s", printable(ids[i]).c_str());
  std::fprintf(stderr, "%s\n", ids.size() > 20 ? " ..." : "");
}

int runMerge(const std::vector<std::string>& sources, std::string out, bool allow_mixed) {
  std::vector<std::string> dirs;
  std::vector<std::string> manifest_dirs;
  for (const std::string& src : sources) {
    std::error_code ec;
    if (!fs::is_directory(src, ec)) throw Error(src + ": not a directory");
    const std::vector<std::string> found = mergeSources(src);
    dirs.insert(dirs.end(), found.begin(), found.end());
    if (found.size() != 1 || found.front() != src) manifest_dirs.push_back(src);
  }
  if (out.empty()) {
    if (sources.size() != 1) throw Error("--out is required when merging several sources");
    out = sources.front();
  } else {
    // A table in --out that is not merged would be replaced, its episodes lost.
    std::error_code ec;
    bool is_source = false;
    for (const std::string& src : sources) is_source = is_source || fs::equivalent(src, out, ec);
    for (const char* table : {"results.jsonl", "results.csv"}) {
      if (!is_source && fs::exists(fs::path(out) / table, ec)) {
        throw Error("--out " + out + ": already holds " + table +
                    ", which is not among the sources; name it as a source too, or choose a "
                    "new --out");
      }
    }
  }
  if (dirs.empty()) throw Error(sources.front() + "/shards: no shard directories");
  const MergeResult r = mergeResults(dirs, manifest_dirs);
  for (const std::string& mix : r.mixes) {
    std::fprintf(stderr, "%s: %s\n", allow_mixed ? "warning" : "mixed", printable(mix).c_str());
  }
  if (!r.mixes.empty() && !allow_mixed) {
    throw Error(
        "the sources mix world contents or parksim builds (listed above): one table would hold "
        "two experiments; run the stale shards again, or merge anyway with --allow-mixed");
  }
  writeMergedTable(out, r);
  std::printf("merged %zu source%s: %zu episodes", dirs.size(), dirs.size() == 1 ? "" : "s",
              r.rows.size());
  if (r.expected > 0) std::printf(" of %zu expected", r.expected);
  std::printf(
      ", %zu missing, %zu duplicated, %zu conflicting\nwrote %s/results.csv and "
      "%s/results.jsonl\n",
      r.missing.size(), r.duplicated.size(), r.conflicting.size(), printable(out).c_str(),
      printable(out).c_str());
  list("missing (run the sweep or its shard again to add them)", r.missing);
  list("duplicated (identical rows, kept once)", r.duplicated);
  list("conflicting (different results for one id; the first source's row kept)", r.conflicting);
  list("not in any manifest", r.unexpected);
  return r.missing.empty() && r.conflicting.empty() ? 0 : 1;
}

}  // namespace

CommandRunner setupMergeCommand(CLI::App& sub) {
  struct Options {
    std::vector<std::string> sources;
    std::string out;
    bool allow_mixed = false;
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("sources", opt->sources,
                 "sweep output directories; one directory with shards/ merges its shards")
      ->required();
  sub.add_option("--out", opt->out, "where to write the merged table (default: the one source)");
  sub.add_flag("--allow-mixed", opt->allow_mixed,
               "merge sources whose rows come from other world contents or parksim builds "
               "(listed as warnings; report flags such a table)");
  return [opt](const OutputOptions&) { return runMerge(opt->sources, opt->out, opt->allow_mixed); };
}

}  // namespace parksim::app
