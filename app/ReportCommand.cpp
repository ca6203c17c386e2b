// parksim report DIR: summary tables and figures of a sweep's results table (DIR/results.jsonl)
// in DIR/report/ (or --out): summary.md and summary.csv per world x planner x realism preset,
// box plots and a success matrix drawn by parksim's renderer, and one OMPL benchmark log per
// world (ompl_<world>.log, with the cost-over-time progress) for Planner Arena; a file named
// after a world or a parameter takes its name through fileStemOf (core/io/FileName.h).
// DIR/report/index.html (or --out) is the same as a page (pages/SweepPage.h): every episode in a
// table that sorts and filters, per-axis summaries, kept episodes linked to their own pages.
// Every row's seal is checked (a changed row stops the report, naming its file and line); rows
// of other world contents or builds, and episode folders cut short, emptied or overwritten
// (pages/EpisodeFolderCheck.h: their pages are not linked), are warnings: one line each on
// stderr, in summary.md and on the page, and their count last ("2 warnings"), as pytest
// counts its warnings.
// Exit status: 0 when written (warnings or not, as pytest's), 2 on bad input.

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/Command.h"
#include "parksim/cli/OutputDir.h"
#include "parksim/cli/ReportFileOption.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/FileName.h"
#include "parksim/pages/EpisodeFolderCheck.h"
#include "parksim/pages/JUnitPageLinks.h"
#include "parksim/pages/SweepPage.h"
#include "parksim/pipeline/Verdict.h"
#include "parksim/report/Report.h"
#include "parksim/results/reports/JUnitReport.h"
#include "parksim/results/reports/OmplLog.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/shards/SweepManifest.h"

namespace parksim::app {

using cli::printable;
using cli::printableLines;
namespace {

using Json = nlohmann::ordered_json;

bench::BenchRecord benchRecord(const Json& row) {
  bench::BenchRecord r;
  r.library = "parksim";
  r.planner = row.value("planner", "?") + (row.value("smooth", false) ? "+smooth" : "");
  r.space = row.value("steering", "?");
  r.scenario = row.value("world", "?");
  r.seed = row.value("seed", std::uint64_t{0});
  r.budget = "iterations=" + std::to_string(row.value("max_iterations", 0));
  if (row.value("tracking", "closed") != "closed") r.budget += ",open-loop";
  r.solved = row.value("plan_solved", false);
  r.status = row.value("plan_status", "");
  // Plans are validated gap-free by construction; "valid" here also asks that the executed
  // episode met its tolerance, so Planner Arena can compare what actually parked.
  r.valid = r.solved && row.value("met_tolerance", false);
  const auto num = [&row](const char* key) {
    const auto it = row.find(key);
    return it != row.end() && it->is_number() ? it->get<double>() : bench::kNotMeasured;
  };
  r.time_first_s = num("plan_first_solution_s");
  r.time_total_s = num("plan_time_s");
  r.length_m = num("plan_path_length_m");
  r.cost = num("plan_cost_m");
  r.cusps = row.value("plan_cusps", -1);
  r.iterations = row.value("plan_iterations", -1L);
  r.tree_size =
      row.value("plan_tree_size", -1L) + std::max(0L, row.value("plan_goal_tree_size", 0L));
  r.collision_queries = row.value("plan_collision_queries", -1L);
  if (const auto it = row.find("plan_cost_history"); it != row.end() && it->is_array()) {
    for (const auto& sample : *it) {
      if (sample.is_array() && sample.size() == 3) {
        r.progress.emplace_back(sample[0].get<double>(), sample[2].get<double>());
      }
    }
  }
  return r;
}

std::vector<std::string> writeOmplLogs(const std::vector<Json>& rows, const std::string& name,
                                       const std::string& out) {
  std::map<std::string, std::vector<bench::BenchRecord>> by_world;
  std::map<std::string, double> total_s;
  std::map<std::string, int> max_iterations;
  for (const Json& row : rows) {
    const bench::BenchRecord r = benchRecord(row);
    by_world[r.scenario].push_back(r);
    if (!std::isnan(r.time_total_s)) total_s[r.scenario] += r.time_total_s;
  }
  std::vector<std::string> written;
  for (const auto& [world, records] : by_world) {
    std::map<std::string, int> runs;
    int runs_per_planner = 0;
    double longest = 0.0;
    for (const bench::BenchRecord& r : records) {
      runs_per_planner = std::max(runs_per_planner, ++runs[r.planner + r.space + r.budget]);
      if (!std::isnan(r.time_total_s)) longest = std::max(longest, r.time_total_s);
    }
    bench::OmplLogInfo info;
    info.experiment = "parksim_sweep_" + name + "_" + world;
    info.host = rows.empty() ? "" : rows.front().value("host", "");
    info.start_time = bench::omplLogTimeNow();
    info.setup = "parksim sweep " + name + ", world " + world +
                 "; plans are validated gap-free; valid = the executed episode met its tolerance";
    info.time_limit_s = longest;
    info.runs_per_planner = runs_per_planner;
    info.total_s = total_s[world];
    const std::string path = out + "/ompl_" + fileStemOf(world) + ".log";
    writeFileAtomically(path, bench::omplBenchmarkLog(info, records));
    written.push_back(path);
  }
  return written;
}

// DIR/report/index.html: the table as a page, linking the episodes' pages (relative to `out`,
// where the report ends up, not the staging directory it is written into).
std::string writeIndexPage(const std::string& dir, const std::string& out, const std::string& name,
                           const std::vector<Json>& rows, const std::vector<std::string>& warnings,
                           const std::string& staged) {
  SweepPage page;
  page.title = name;
  page.source = dir;
  page.rows = &rows;
  page.axes = parameterColumns(rows);
  for (const EpisodeStatus s : allEpisodeStatuses()) page.statuses.push_back(toString(s));
  page.episodes_href = hrefOf(relativeHref(out, dir + "/episodes"));
  page.kept = keptEpisodePages(dir + "/episodes", rows);
  page.warnings = warnings;
  const std::string path = staged + "/index.html";
  writeSweepPage(path, page);
  return path;
}

int runReport(const std::string& dir, std::string out, const std::string& junit) {
  const std::string path = dir + "/results.jsonl";
  if (!std::filesystem::exists(path))
    throw Error(path + ": no such file (run parksim sweep first)");
  const VerifiedTable table = readVerifiedTable(path);
  const std::vector<Json>& rows = table.rows;
  if (rows.empty()) throw Error(path + ": no results yet");
  const std::vector<std::string> mixes = table.origins.mixes();
  const std::vector<std::string> damaged = episodeFolderProblems(dir + "/episodes", rows);
  std::vector<std::string> warnings = mixes;
  warnings.insert(warnings.end(), damaged.begin(), damaged.end());
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", printable(w).c_str());
  if (out.empty()) out = dir + "/report";
  SweepManifest manifest;
  std::string name = std::filesystem::path(dir).filename().string();
  if (readSweepManifest(dir, manifest) && !manifest.name.empty()) name = manifest.name;
  // As plan and run do: the report is written whole into a staging directory and swapped in, and
  // an --out holding files parksim did not write (a home directory, the sweep directory itself)
  // is refused instead of being written into.
  cli::OutputDir staged(out);
  std::vector<std::string> written = writeReport(rows, name, staged.path());
  const std::vector<std::string> logs = writeOmplLogs(rows, name, staged.path());
  written.insert(written.end(), logs.begin(), logs.end());
  written.push_back(writeIndexPage(dir, out, name, rows, warnings, staged.path()));
  std::string summary;
  {
    std::FILE* f = std::fopen((staged.path() + "/summary.md").c_str(), "r");
    if (f != nullptr) {
      char buf[4096];
      std::size_t n = 0;
      while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) summary.append(buf, n);
      std::fclose(f);
    }
  }
  if (!mixes.empty()) {
    summary +=
        "\n**Warning: this table mixes world contents or parksim builds** (`parksim verify` "
        "lists them):\n\n";
    for (const std::string& mix : mixes) summary += "- " + mix + "\n";
  }
  if (!damaged.empty()) {
    summary +=
        "\n**Warning: episode folders cut short, emptied or overwritten** (their pages are "
        "not linked):\n\n";
    for (const std::string& d : damaged) summary += "- " + d + "\n";
  }
  if (!warnings.empty()) writeFileAtomically(staged.path() + "/summary.md", summary);
  staged.commit();
  if (!junit.empty()) {
    JUnitReport report = episodesJUnit(rows, name, rowGroupNameOf);
    linkJUnitToPages(report, junit, out + "/index.html", dir + "/episodes");
    writeJUnitFile(junit, report);
    written.push_back(junit);
  }
  std::printf("%s\n", printableLines(summary).c_str());
  for (const std::string& w : written) {
    std::printf("wrote %s\n", printable(staged.shown(w)).c_str());
  }
  if (!warnings.empty()) {
    std::fflush(stdout);
    std::fprintf(stderr, "%zu warning%s\n", warnings.size(), warnings.size() == 1 ? "" : "s");
  }
  return 0;
}

}  // namespace

CommandRunner setupReportCommand(CLI::App& sub) {
  struct Options {
    std::string dir;
    std::string out;
    std::string junit;
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("dir", opt->dir, "a sweep's output directory (with results.jsonl)")->required();
  sub.add_option("--out", opt->out, "where to write the report (default: DIR/report)");
  cli::addReportFileOption(sub, "--junit", opt->junit,
                           "also write the table as a JUnit XML report: one test case per "
                           "episode, one suite per world x planner x realism (docs/ci.md)");
  return [opt](const OutputOptions&) { return runReport(opt->dir, opt->out, opt->junit); };
}

}  // namespace parksim::app
