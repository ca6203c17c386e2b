// parksim sweep SPEC --out DIR: expands the spec into episodes with stable ids, runs plan +
// simulate + measure on worker threads and appends each finished episode to DIR/results.jsonl
// and DIR/results.csv. Resumable: run the same command again and only the episodes missing
// from the table run. --shard I/N runs a deterministic part; --slurm writes DIR/sweep.sbatch, a
// job array with one task per shard, instead of running anything (docs/sweeps.md).
// Exit status: 0 when every episode (of the shard) met its tolerance, 1 when some did not,
// 2 on bad input, 3 on an internal error.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include "app/Command.h"
#include "parksim/cli/ReportFileOption.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/sweep/EpisodeExpansion.h"
#include "parksim/sweep/ResultsJUnit.h"
#include "parksim/sweep/ResultsTable.h"
#include "parksim/sweep/Shard.h"
#include "parksim/sweep/SlurmScript.h"
#include "parksim/sweep/SweepManifest.h"
#include "parksim/sweep/SweepRunner.h"
#include "parksim/sweep/SweepSpecReader.h"

namespace parksim::app {

using cli::printable;
using cli::printableLines;
namespace {

namespace fs = std::filesystem;

struct SweepOptions {
  std::string spec;
  std::string out;
  int workers = 0;
  std::string shard = "0/1";
  bool progress = false;
  bool slurm = false;
  SlurmDef slurm_def;
  int slurm_shards = 0;
  int slurm_max_parallel = 0;
  std::string junit;
};

std::string duration(double s) {
  if (!(s >= 0.0) || s > 360000.0) return "?";
  const long t = std::lround(s);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return buf;
}

// The progress line: rewritten in place on a terminal, or one line now and then in a log.
class ProgressPrinter {
 public:
  ProgressPrinter(bool tty, std::size_t already_done) : tty_(tty), already_(already_done) {}

  void operator()(const SweepProgress& p) {
    const bool last = p.done == p.total;
    if (!tty_) {
      const auto now = std::chrono::steady_clock::now();
      if (!last && p.ran > 0 && now - last_print_ < std::chrono::seconds(10)) return;
      last_print_ = now;
    }
    const double rate = p.elapsed_s > 0.0 ? p.ran / p.elapsed_s : 0.0;
    const double eta = rate > 0.0 ? (p.total - p.done) / rate : -1.0;
    std::fprintf(stderr, "%s%zu/%zu episodes done (%.0f%%), %zu failed, %.2f episodes/s, ETA %s%s",
                 tty_ ? "\r\033[K" : "", p.done, p.total,
                 p.total > 0 ? 100.0 * p.done / p.total : 100.0, p.failed, rate,
                 p.ran > 0 ? duration(eta).c_str() : "?", tty_ && !last ? "" : "\n");
    std::fflush(stderr);
  }

 private:
  bool tty_;
  std::size_t already_;
  std::chrono::steady_clock::time_point last_print_{};
};

std::string selfExe() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("parksim") : p.string();
}

int writeSlurm(const SweepOptions& o, const SweepSpec& spec,
               const std::vector<SweepEpisode>& episodes) {
  SlurmDef d = o.slurm_def;
  const int wanted = o.slurm_shards > 0 ? o.slurm_shards : 10;
  d.shards =
      static_cast<int>(std::min<std::size_t>(wanted, std::max<std::size_t>(1, episodes.size())));
  d.job_name = "parksim-" + spec.name;
  if (o.slurm_max_parallel > 0) d.max_parallel = "%" + std::to_string(o.slurm_max_parallel);
  d.parksim_exe = selfExe();
  d.spec_path = fs::absolute(o.spec).lexically_normal().string();
  d.out_dir = fs::absolute(o.out).lexically_normal().string();
  const std::string script = sbatchScript(d);  // checks the options before DIR is touched
  ensureDirectory(o.out + "/logs");
  ensureDirectory(o.out + "/shards");
  SweepManifest manifest{o.spec, spec.name, Shard{}, {}};
  for (const SweepEpisode& e : episodes) manifest.episode_ids.push_back(e.id);
  writeSweepManifest(o.out, manifest);
  const std::string path = o.out + "/sweep.sbatch";
  writeFileAtomically(path, script);
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  std::printf(
      "wrote %s: %zu episodes in %d array tasks (%d CPU%s, %s, %s each)\n"
      "submit:  sbatch --wait %s\nthen:    %s merge %s\n",
      printable(path).c_str(), episodes.size(), d.shards, d.cpus_per_task,
      d.cpus_per_task == 1 ? "" : "s", d.mem.c_str(), d.time.c_str(), printable(path).c_str(),
      printable(d.parksim_exe).c_str(), printable(o.out).c_str());
  return 0;
}

int runSweepCommand(const SweepOptions& o) {
  // Everything is read and checked before DIR is touched.
  const SweepSpec spec = loadSweepSpec(o.spec);
  const std::vector<SweepWorld> worlds = loadSweepWorlds(spec);
  const std::vector<SweepEpisode> all = expandEpisodes(spec, worlds);
  const Shard shard = parseShard(o.shard);
  if (o.slurm) {
    if (o.shard != "0/1") throw Error("--slurm writes a script for every shard; drop --shard");
    if (!o.junit.empty()) {
      throw Error("--junit: --slurm runs nothing; after the jobs, parksim report DIR --junit FILE");
    }
    return writeSlurm(o, spec, all);
  }
  const int workers = o.workers > 0
                          ? o.workers
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const std::vector<SweepEpisode> episodes = selectShard(all, shard);

  // A table of another id format (an older parksim's) is refused before anything is written.
  SweepManifest existing;
  (void)readSweepManifest(o.out, existing);
  ResultsTable table(o.out);  // refuses a table with other columns before anything is written
  SweepManifest manifest{o.spec, spec.name, shard, {}};
  for (const SweepEpisode& e : all) manifest.episode_ids.push_back(e.id);
  writeSweepManifest(o.out, manifest);

  SweepRunnerDef def;
  def.workers = workers;
  def.episode.record = spec.record;
  def.episode.episodes_dir = o.out + "/episodes";

  std::size_t already = 0;
  for (const SweepEpisode& e : episodes) already += table.done().count(e.id);
  std::fprintf(
      stderr, "parksim sweep %s: %zu episodes%s, %zu already in %s/results.jsonl, %d worker%s\n",
      spec.name.c_str(), episodes.size(),
      shard.count > 1 ? (" (shard " + o.shard + " of " + std::to_string(all.size()) + ")").c_str()
                      : "",
      already, printable(o.out).c_str(), workers, workers == 1 ? "" : "s");
  const bool tty = isatty(STDERR_FILENO) == 1;
  SweepProgressFn progress;
  if (tty || o.progress) progress = ProgressPrinter(tty, already);
  const SweepProgress p = runSweep(episodes, def, table, progress);
  if (!o.junit.empty()) {
    // The shard's episodes, those of earlier runs included (as the exit status counts them).
    std::set<std::string> ids;
    for (const SweepEpisode& e : episodes) ids.insert(e.id);
    std::vector<nlohmann::ordered_json> rows;
    for (nlohmann::ordered_json& row : readResultsJsonl(o.out + "/results.jsonl")) {
      if (ids.count(row.value("episode_id", "")) > 0) rows.push_back(std::move(row));
    }
    writeJUnitFile(o.junit, resultsJUnit(rows, spec.name));
  }

  // The verdict covers the shard's episodes, those of earlier runs included.
  std::size_t failed = 0;
  for (const SweepEpisode& e : episodes) failed += table.done().at(e.id) ? 0 : 1;
  std::printf(
      "sweep %s: %zu episodes, %zu run now in %.1f s (%.2f episodes/s); %zu met their "
      "tolerance, %zu did not\nwrote %s/results.csv and %s/results.jsonl\n",
      spec.name.c_str(), episodes.size(), p.ran, p.elapsed_s,
      p.elapsed_s > 0.0 ? p.ran / p.elapsed_s : 0.0, episodes.size() - failed, failed,
      printable(o.out).c_str(), printable(o.out).c_str());
  if (failed > 0) {
    std::size_t listed = 0;
    for (const nlohmann::ordered_json& row : readResultsJsonl(o.out + "/results.jsonl")) {
      if (row.value("met_tolerance", false) || listed == 10) continue;
      const std::string id = row["episode_id"].get<std::string>();
      if (std::none_of(episodes.begin(), episodes.end(),
                       [&](const SweepEpisode& e) { return e.id == id; })) {
        continue;
      }
      ++listed;
      std::fprintf(stderr, "  failed %s: %s %s seed %s: %s\n", id.c_str(),
                   row.value("world", "").c_str(), row.value("planner", "").c_str(),
                   row["seed"].dump().c_str(), printable(row.value("failure", "")).c_str());
    }
    if (failed > listed) std::fprintf(stderr, "  ... and %zu more\n", failed - listed);
    return 1;
  }
  return 0;
}

}  // namespace

CommandRunner setupSweepCommand(CLI::App& sub) {
  auto opt = std::make_shared<SweepOptions>();
  sub.add_option("spec", opt->spec, "sweep spec (YAML, see docs/sweeps.md)")->required();
  sub.add_option("--out", opt->out, "output directory (results.csv, results.jsonl, episodes/)")
      ->required();
  sub.add_option("--workers", opt->workers, "worker threads (default: one per CPU)")
      ->check(CLI::Range(1, 1024));
  sub.add_option("--shard", opt->shard,
                 "run only shard I of N (I from 0): the episodes at positions I, I+N, ... of the "
                 "sweep's canonical order")
      ->capture_default_str();
  sub.add_flag("--slurm", opt->slurm,
               "write OUT/sweep.sbatch (a Slurm job array, one task per shard) instead of "
               "running");
  sub.add_option("--slurm-shards", opt->slurm_shards,
                 "array tasks (default 10, at most one per episode)")
      ->check(CLI::Range(1, 100000));
  sub.add_option("--slurm-cpus", opt->slurm_def.cpus_per_task,
                 "CPUs per task (the task's --workers)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  sub.add_option("--slurm-mem", opt->slurm_def.mem, "memory per task")->capture_default_str();
  sub.add_option("--slurm-time", opt->slurm_def.time, "time limit per task")->capture_default_str();
  sub.add_option("--slurm-partition", opt->slurm_def.partition,
                 "partition (default: the cluster's)");
  sub.add_option("--slurm-account", opt->slurm_def.account, "account to charge");
  sub.add_option("--slurm-max-parallel", opt->slurm_max_parallel,
                 "at most this many tasks at once (the array's %K throttle)")
      ->check(CLI::Range(1, 100000));
  cli::addReportFileOption(sub, "--junit", opt->junit,
                           "also write a JUnit XML report: one test case per episode (of the "
                           "shard), one suite per world x planner x realism (docs/ci.md)");
  // --progress is every command's (main.cpp): not a terminal, the line comes every 10 s.
  return [opt](const OutputOptions& output) {
    opt->progress = output.progress;
    return runSweepCommand(*opt);
  };
}

}  // namespace parksim::app
