// parksim compare BASELINE CANDIDATE: did the candidate sweep get worse than the baseline?
// Per world x planner x realism group: the success rate (exact test), the median and p95 of
// the max tracking error and of the goal error (bootstrap), paired by episode id where both
// tables hold the same episodes, Holm-corrected over every test (parksim/compare/,
// docs/ci.md). --across planner (controller, ...): tables of two planners or controllers, rows
// paired when every other parameter is equal (compare/RowPairing.h). Prints the Markdown summary;
// --markdown and --junit write it for a CI page. Exit status: 0 no regression, 4 regression, 2 bad
// input.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "app/Command.h"
#include "parksim/cli/ReportFileOption.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/cli/Validators.h"
#include "parksim/compare/ComparedTable.h"
#include "parksim/compare/ComparisonJson.h"
#include "parksim/compare/ComparisonReport.h"
#include "parksim/compare/ConfigurationDiff.h"
#include "parksim/compare/RowPairing.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/pages/ComparisonPage.h"
#include "parksim/sweep/shards/SweepManifest.h"

namespace parksim::app {

namespace {

struct CompareOptions {
  std::string baseline;
  std::string candidate;
  CompareDef def;
  double max_increase_percent = 100.0 * CompareDef{}.max_increase;
  double min_increase_mm = 1e3 * CompareDef{}.min_increase_m;
  double max_success_drop_percent = 100.0 * CompareDef{}.max_success_drop;
  std::string markdown;
  std::string junit;
  std::string html;
};

// The sweep directory of a table as given: the directory itself, or a results.jsonl's folder.
std::string sweepDir(const std::string& table) {
  if (std::filesystem::is_directory(table)) return table;
  const std::string folder = std::filesystem::path(table).parent_path().string();
  return folder.empty() ? "." : folder;
}

// The text of the spec the sweep in `dir` was run from (its sweep.json names it, as given on
// the sweep's command line), or "" when there is none or it cannot be read: the comparison
// then lists the columns that differ only.
std::string specTextOf(const std::string& dir) {
  SweepManifest manifest;
  try {
    if (!readSweepManifest(dir, manifest) || manifest.spec_path.empty()) return "";
  } catch (const Error&) {
    return "";
  }
  std::ifstream in(manifest.spec_path, std::ios::binary);
  if (!in) return "";
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

int runCompare(CompareOptions o) {
  o.def.max_increase = o.max_increase_percent / 100.0;
  o.def.min_increase_m = o.min_increase_mm / 1e3;
  o.def.max_success_drop = o.max_success_drop_percent / 100.0;
  checkCompareDef(o.def);
  const ComparedTable baseline = readComparedTable(o.baseline);
  const ComparedTable candidate = readComparedTable(o.candidate);
  // As report does: rows of another world content or build are flagged, not silently pooled.
  for (const ComparedTable* table : {&baseline, &candidate}) {
    for (const std::string& mix : table->mixes) {
      std::fprintf(stderr, "warning: %s\n", cli::printable(mix).c_str());
    }
  }
  const TableComparison t = compareTables(baseline.rows, candidate.rows, o.def);
  const ComparisonSources sources{o.baseline, o.candidate, static_cast<int>(baseline.rows.size()),
                                  static_cast<int>(candidate.rows.size())};
  const std::string markdown = comparisonMarkdown(t, o.def, sources);
  if (!o.markdown.empty()) writeFileAtomically(o.markdown, markdown);
  if (!o.junit.empty()) writeJUnitFile(o.junit, comparisonJUnit(t, o.def));
  if (!o.html.empty()) {
    ComparisonPage page;
    page.comparison = comparisonJson(t, o.def, sources, baseline.rows, candidate.rows);
    page.baseline_dir = sweepDir(o.baseline);
    page.candidate_dir = sweepDir(o.candidate);
    std::vector<ConfigurationDifference> differences =
        columnDifferences(baseline.rows, candidate.rows);
    const std::string baseline_spec = specTextOf(page.baseline_dir);
    const std::string candidate_spec = specTextOf(page.candidate_dir);
    if (!baseline_spec.empty() && !candidate_spec.empty()) {
      const auto lines = specDifferences(baseline_spec, candidate_spec);
      differences.insert(differences.end(), lines.begin(), lines.end());
    }
    page.comparison["differences"] = differencesJson(differences);
    writeComparisonPage(o.html, page);
  }
  std::printf("%s", cli::printableLines(markdown).c_str());
  return t.regression() ? kExitToleranceNotMet : kExitOk;
}

}  // namespace

CommandRunner setupCompareCommand(CLI::App& sub) {
  using cli::integerIn;
  using cli::realIn;
  auto opt = std::make_shared<CompareOptions>();
  sub.add_option("baseline", opt->baseline, "the baseline: a sweep directory or its results.jsonl")
      ->required();
  sub.add_option("candidate", opt->candidate,
                 "the candidate: a sweep directory or its results.jsonl")
      ->required();
  sub.add_option("--confidence", opt->def.confidence,
                 "family-wise confidence: unchanged code raises no alarm with at least this "
                 "probability (Holm over every test)")
      ->capture_default_str()
      ->check(realIn(0.5, 0.9999));
  sub.add_option("--max-increase-percent", opt->max_increase_percent,
                 "an error quantile is a regression when it grew by more than this share of "
                 "the baseline's ...")
      ->capture_default_str()
      ->check(realIn(0.0, 1000.0));
  sub.add_option("--min-increase-mm", opt->min_increase_mm, "... and by more than this")
      ->capture_default_str()
      ->check(realIn(0.0, 1000.0));
  sub.add_option("--max-success-drop-percent", opt->max_success_drop_percent,
                 "the success rate is a regression when significantly lower and lower by more "
                 "than these percentage points")
      ->capture_default_str()
      ->check(realIn(0.0, 100.0));
  sub.add_option("--resamples", opt->def.resamples, "bootstrap resamples per quantile test")
      ->capture_default_str()
      ->check(integerIn(100, 10000000));
  sub.add_option("--seed", opt->def.seed, "seed of the bootstrap")
      ->capture_default_str()
      ->check(cli::unsigned64());
  sub.add_option("--min-samples", opt->def.min_samples,
                 "a group with fewer episodes on either side has its quantiles not tested")
      ->capture_default_str()
      ->check(integerIn(2, 1000000));
  sub.add_option("--across", opt->def.across,
                 "parameter columns the tables differ in by design (planner, controller, "
                 "planner.NAME, controller.NAME): groups are keyed and rows paired without them")
      ->delimiter(',')
      ->type_name("COLUMN[,COLUMN...]")
      ->check(CLI::Validator([](std::string& column) { return acrossColumnProblem(column); },
                             "COLUMN"));
  cli::addReportFileOption(sub, "--markdown", opt->markdown,
                           "also write the summary to this Markdown file (a CI job summary)");
  cli::addReportFileOption(sub, "--junit", opt->junit,
                           "also write a JUnit XML report: a suite per group, a test case per "
                           "metric, failed where it regressed");
  cli::addReportFileOption(sub, "--html", opt->html,
                           "also write the comparison as a page that opens from file:// "
                           "(groups, intervals, p-values, links to the paired episodes' pages)");
  return [opt](const OutputOptions&) { return runCompare(*opt); };
}

}  // namespace parksim::app
