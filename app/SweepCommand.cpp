// parksim sweep SPEC --out DIR: expands the spec into episodes with stable ids, runs plan +
// simulate + measure on worker threads and appends each finished episode to DIR/results.jsonl
// and DIR/results.csv. Resumable: run the same command again and only the episodes missing
// from the table run. --shard I/N runs a deterministic part; --slurm writes DIR/sweep.sbatch, a
// job array with one task per shard, instead of running anything; --slurm --missing finds the
// shards whose tasks died and submits them again (docs/sweeps.md).
// A resumed table must hold sealed rows of the same world contents and build (ResultsTable.h).
// Exit status: 0 when every episode (of the shard) met its tolerance, 1 when some did not,
// 2 on bad input, 3 on an internal error.

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include "app/Command.h"
#include "parksim/cli/ComponentOptions.h"
#include "parksim/cli/Progress.h"
#include "parksim/cli/ReportFileOption.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/system/ChildProcess.h"
#include "parksim/report/Report.h"
#include "parksim/results/reports/JUnitReport.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/results/tables/RowSeal.h"
#include "parksim/sweep/run/SweepJob.h"
#include "parksim/sweep/run/SweepRunner.h"
#include "parksim/sweep/shards/Shard.h"
#include "parksim/sweep/shards/SlurmResubmit.h"
#include "parksim/sweep/shards/SlurmScript.h"
#include "parksim/sweep/shards/SweepManifest.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/SweepSpecReader.h"

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
  bool missing = false;  // with --slurm: submit the incomplete shards again
  bool wait = false;     // with --missing: wait for the tasks to end
  SlurmDef slurm_def;
  int slurm_shards = 0;
  int slurm_max_parallel = 0;
  // The --slurm-* request options this command line gives; with --missing the others are
  // what sweep.json recorded of the first submission.
  std::set<std::string> slurm_given;
  std::string junit;
  bool list = false;               // print the episodes and run nothing
  cli::PluginOptions plugins;      // besides the spec's plugins:
  cli::UserCodeOptions user_code;  // the limits on user code: workers and commands
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
  explicit ProgressPrinter(bool tty) : tty_(tty) {}

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
    cli::markProgressLineOpen(tty_ && !last);
  }

 private:
  bool tty_;
  std::chrono::steady_clock::time_point last_print_{};
};

// Ctrl-C, SIGTERM or SIGHUP end a sweep as their default action would: the table holds whole
// rows whenever the process dies (ResultsTable.h). First an open progress line is ended, so the
// shell's prompt starts on a line of its own. The signals are blocked in every thread made
// while this lives and taken by a watcher thread.
class SignalWatcher {
 public:
  SignalWatcher() {
    sigset_t set = signals();
    pthread_sigmask(SIG_BLOCK, &set, &old_mask_);
    watcher_ = std::thread([this] { watch(); });
    // Worker processes are forked next: not while this thread is starting (OutputDir.cpp).
    while (!started_.load()) std::this_thread::yield();
  }
  ~SignalWatcher() {
    stop_ = true;
    watcher_.join();
    pthread_sigmask(SIG_SETMASK, &old_mask_, nullptr);
  }
  SignalWatcher(const SignalWatcher&) = delete;
  SignalWatcher& operator=(const SignalWatcher&) = delete;

 private:
  static sigset_t signals() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, sig);
    return set;
  }
  void watch() {
    const sigset_t set = signals();
    started_.store(true);
    while (!stop_.load()) {
      const timespec wait{0, 50'000'000};
      const int sig = sigtimedwait(&set, nullptr, &wait);
      if (sig <= 0) continue;
      killChildProcessGroups();  // planner and controller commands, and what they started
      cli::endOpenProgressLine();
      ::signal(sig, SIG_DFL);
      sigset_t one;
      sigemptyset(&one);
      sigaddset(&one, sig);
      pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
      ::raise(sig);
    }
  }
  sigset_t old_mask_{};
  std::atomic<bool> stop_{false};
  std::atomic<bool> started_{false};
  std::thread watcher_;
};

std::string selfExe() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("parksim") : p.string();
}

// Writes DIR/sweep.sbatch for `shards` array tasks and DIR/sweep.json; returns the script's path.
std::string writeSlurmFiles(const SweepOptions& o, const SweepSpec& spec,
                            const std::vector<SweepEpisode>& episodes, int shards, SlurmDef& d) {
  d = o.slurm_def;
  d.shards = shards;
  d.job_name = "parksim-" + spec.name;
  if (o.slurm_max_parallel > 0) d.max_parallel = "%" + std::to_string(o.slurm_max_parallel);
  d.parksim_exe = selfExe();
  d.spec_path = fs::absolute(o.spec).lexically_normal().string();
  d.out_dir = fs::absolute(o.out).lexically_normal().string();
  const std::string script = sbatchScript(d);  // checks the options before DIR is touched
  ensureDirectory(o.out + "/logs");
  ensureDirectory(o.out + "/shards");
  SweepManifest manifest{o.spec, spec.name, Shard{}, {}, d.shards, d};
  for (const SweepEpisode& e : episodes) manifest.episode_ids.push_back(e.id);
  writeSweepManifest(o.out, manifest);
  const std::string path = o.out + "/sweep.sbatch";
  writeFileAtomically(path, script);
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  return path;
}

int writeSlurm(const SweepOptions& o, const SweepSpec& spec,
               const std::vector<SweepEpisode>& episodes) {
  const int wanted = o.slurm_shards > 0 ? o.slurm_shards : 10;
  const int shards =
      static_cast<int>(std::min<std::size_t>(wanted, std::max<std::size_t>(1, episodes.size())));
  SlurmDef d;
  const std::string path = writeSlurmFiles(o, spec, episodes, shards, d);
  std::printf(
      "wrote %s: %zu episodes in %d array tasks (%d CPU%s, %s, %s each)\n"
      "submit:  sbatch --wait %s\nthen:    %s merge %s\n",
      printable(path).c_str(), episodes.size(), d.shards, d.cpus_per_task,
      d.cpus_per_task == 1 ? "" : "s", d.mem.c_str(), d.time.c_str(), printable(path).c_str(),
      printable(d.parksim_exe).c_str(), printable(o.out).c_str());
  return 0;
}

// --slurm --missing: the shards whose tables lack episodes (tasks that died) are submitted
// again, and only those; a shard whose table a task still holds is left alone.
int resubmitMissing(const SweepOptions& o, const SweepSpec& spec,
                    const std::vector<SweepEpisode>& all) {
  SweepManifest manifest;
  if (!readSweepManifest(o.out, manifest) || manifest.slurm_shards < 1) {
    throw Error(o.out + "/sweep.json: no Slurm sweep here; write one first: parksim sweep " +
                o.spec + " --out " + o.out + " --slurm");
  }
  std::vector<std::string> ids;
  for (const SweepEpisode& e : all) ids.push_back(e.id);
  if (ids != manifest.episode_ids) {
    throw Error(o.spec + ": expands to other episodes than " + o.out +
                "/sweep.json records (the spec or a world changed since --slurm wrote it); "
                "write the script again with --slurm and submit it whole (every shard resumes)");
  }
  const int shards = manifest.slurm_shards;
  if (o.slurm_shards > 0 && o.slurm_shards != shards) {
    throw Error("--slurm-shards " + std::to_string(o.slurm_shards) + ": the sweep in " + o.out +
                " was dealt to " + std::to_string(shards) + " shards, which --missing keeps");
  }
  const std::vector<ShardState> states = slurmShardStates(o.out, all, shards);
  std::size_t missing = 0;
  for (const ShardState& st : states) {
    if (st.complete()) continue;
    missing += st.episodes - st.done;
    std::fprintf(stderr, "shard %d: %zu of %zu episodes done%s\n", st.index, st.done, st.episodes,
                 st.running ? " (a task holds its table: still running, not submitted)" : "");
  }
  const std::string list = arrayList(states);
  if (list.empty()) {
    std::printf("%s: %s; nothing submitted\n", printable(o.out).c_str(),
                missing == 0 ? "every shard is complete" : "the incomplete shards are running");
    return 0;
  }
  // The tasks ask for what the first submission asked (a resubmission with the defaults could
  // ask for less memory than the episodes need), except where this command line says otherwise.
  SweepOptions again = o;
  if (manifest.slurm_request) {
    const SlurmDef& asked = *manifest.slurm_request;
    // A recorded word is checked here, so that an edited sweep.json is named as the culprit.
    const std::string recorded_in = o.out + "/sweep.json: slurm_request.";
    const auto keep = [&](const char* option, const char* key, std::string& field,
                          const std::string& recorded, auto check) {
      if (o.slurm_given.count(option) > 0) return;
      check(recorded, recorded_in + key + " (" + option + " overrides it)");
      field = recorded;
    };
    if (o.slurm_given.count("--slurm-cpus") == 0) {
      again.slurm_def.cpus_per_task = asked.cpus_per_task;
    }
    keep("--slurm-mem", "mem", again.slurm_def.mem, asked.mem, checkSbatchWord);
    keep("--slurm-time", "time", again.slurm_def.time, asked.time, checkSbatchWord);
    keep("--slurm-partition", "partition", again.slurm_def.partition, asked.partition,
         checkSbatchWord);
    keep("--slurm-account", "account", again.slurm_def.account, asked.account, checkSbatchWord);
    keep("--slurm-max-parallel", "max_parallel", again.slurm_def.max_parallel, asked.max_parallel,
         checkArrayThrottle);
  }
  SlurmDef d;
  const std::string script = writeSlurmFiles(again, spec, all, shards, d);
  // The throttle goes with the list: sbatch's --array replaces the script's whole #SBATCH one.
  const Submission sub =
      submitArrayTasks(script, list + d.max_parallel, o.wait, o.out + "/logs/sbatch-missing.log");
  std::printf("submitted job %s: array tasks %s of %d (%zu episodes missing)\n", sub.job_id.c_str(),
              list.c_str(), shards, missing);
  if (!o.wait) return 0;
  std::printf("job %s ended (sbatch exit status %d); then: %s merge %s\n", sub.job_id.c_str(),
              sub.exit_code, printable(d.parksim_exe).c_str(), printable(o.out).c_str());
  return sub.exit_code == 0 ? 0 : 1;
}

// Lists up to ten failed episodes of the shard (sorted `episodes`), reading the table one row
// at a time.
void listFailures(const std::string& out, const std::vector<SweepEpisode>& episodes,
                  std::size_t failed) {
  std::size_t listed = 0;
  scanResultsJsonl(out + "/results.jsonl", [&](const TableRow& r) {
    const nlohmann::ordered_json& row = r.row;
    if (row.value("met_tolerance", false) || listed == 10) return;
    const std::string id = row["episode_id"].get<std::string>();
    const auto it = std::lower_bound(
        episodes.begin(), episodes.end(), id,
        [](const SweepEpisode& e, const std::string& value) { return e.id < value; });
    if (it == episodes.end() || it->id != id) return;  // another shard's
    ++listed;
    std::fprintf(stderr, "  failed %s: %s %s seed %s: %s\n", id.c_str(),
                 printable(row.value("world", "")).c_str(), row.value("planner", "").c_str(),
                 row["seed"].dump().c_str(), printable(row.value("failure", "")).c_str());
  });
  if (failed > listed) std::fprintf(stderr, "  ... and %zu more\n", failed - listed);
}

int runSweepCommand(const SweepOptions& o) {
  // Everything is read and checked before DIR is touched.
  // --plugin adds to the spec's plugins: (loaded first, so the spec's may not reuse a name).
  std::shared_ptr<const Components> extra;
  if (!o.plugins.paths.empty()) extra = o.plugins.load();
  const SweepPlan plan =
      prepareSweep(o.spec, extra.get(), {.limits = o.user_code.limits, .isolate = true});
  const SweepSpec& spec = plan.spec;
  // Each world's warnings once, as read from its file (World::warnings).
  for (const SweepWorld& w : plan.worlds) {
    for (const std::string& line : w->world.warnings) {
      std::fprintf(stderr, "warning: %s\n", line.c_str());
    }
  }
  const std::vector<SweepEpisode>& all = plan.episodes;
  const Shard shard = parseShard(o.shard);
  if (o.list) {
    // What the spec expands to (this shard's share), run nothing, write nothing: a sampled
    // spec's draws can be read before a cluster spends hours on them.
    if (!o.junit.empty() || o.slurm) throw Error("--list runs nothing: drop --junit and --slurm");
    std::string out;
    for (const SweepEpisode& e : selectShard(all, shard)) {
      out += e.id + "\t" + canonicalString(e.params) + "\n";
    }
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
  }
  if (o.missing && !o.slurm) throw Error("--missing works on a Slurm sweep: add --slurm");
  if (o.wait && !o.missing) throw Error("--wait waits for the tasks --slurm --missing submits");
  if (o.slurm) {
    if (o.shard != "0/1") throw Error("--slurm writes a script for every shard; drop --shard");
    if (!o.plugins.paths.empty()) {
      throw Error("--plugin: a Slurm task runs the spec alone; name the plugins in its plugins:");
    }
    if (!o.junit.empty()) {
      throw Error("--junit: --slurm runs nothing; after the jobs, parksim report DIR --junit FILE");
    }
    return o.missing ? resubmitMissing(o, spec, all) : writeSlurm(o, spec, all);
  }
  const int workers = o.workers > 0 ? o.workers : defaultSweepWorkers();
  SweepRunnerDef def;
  def.workers = workers;
  def.limits = o.user_code.limits;
  const bool tty = isatty(STDERR_FILENO) == 1;
  SweepProgressFn progress;
  if (tty || o.progress) progress = ProgressPrinter(tty);
  const auto started = [&](const SweepStart& s) {
    for (const std::string& repair : s.repairs) {
      std::fprintf(stderr, "repaired %s\n", printable(repair).c_str());
    }
    std::fprintf(
        stderr, "parksim sweep %s: %zu episodes%s, %zu already in %s/results.jsonl, %d worker%s\n",
        spec.name.c_str(), s.episodes,
        shard.count > 1 ? (" (shard " + o.shard + " of " + std::to_string(all.size()) + ")").c_str()
                        : "",
        s.already, printable(o.out).c_str(), workers, workers == 1 ? "" : "s");
  };
  const SweepJobResult job = [&] {
    const SignalWatcher signals;
    return runSweepJob(plan, shard, o.out, def, started, progress);
  }();
  const std::vector<SweepEpisode>& episodes = job.episodes;
  const SweepProgress& p = job.progress;
  if (!o.junit.empty()) {
    // The shard's episodes, those of earlier runs included (as the exit status counts them).
    std::set<std::string> ids;
    for (const SweepEpisode& e : episodes) ids.insert(e.id);
    std::vector<nlohmann::ordered_json> rows;
    for (nlohmann::ordered_json& row : readResultsJsonl(o.out + "/results.jsonl")) {
      if (ids.count(row.value("episode_id", "")) > 0) rows.push_back(std::move(row));
    }
    writeJUnitFile(o.junit, episodesJUnit(rows, spec.name, rowGroupNameOf));
  }

  // The verdict covers the shard's episodes, those of earlier runs included.
  const std::size_t failed = job.failed;
  std::printf(
      "sweep %s: %zu episodes, %zu run now in %.1f s (%.2f episodes/s); %zu met their "
      "tolerance, %zu did not\nwrote %s/results.csv and %s/results.jsonl\n",
      spec.name.c_str(), episodes.size(), p.ran, p.elapsed_s,
      p.elapsed_s > 0.0 ? p.ran / p.elapsed_s : 0.0, episodes.size() - failed, failed,
      printable(o.out).c_str(), printable(o.out).c_str());
  if (failed > 0) {
    listFailures(o.out, episodes, failed);
    return 1;
  }
  return 0;
}

}  // namespace

CommandRunner setupSweepCommand(CLI::App& sub) {
  auto opt = std::make_shared<SweepOptions>();
  sub.add_option("spec", opt->spec, "sweep spec (YAML, see docs/sweeps.md)")->required();
  CLI::Option* out =
      sub.add_option("--out", opt->out, "output directory (results.csv, results.jsonl, episodes/)");
  sub.add_flag("--list", opt->list,
               "print the spec's episodes (of --shard), one line each: the episode id, a tab and "
               "its canonical parameters (docs/sweeps.md); run nothing")
      ->excludes(out);
  sub.add_option("--workers", opt->workers,
                 "workers: threads, or processes when a planner or controller is user code "
                 "(default: one per CPU)")
      ->check(CLI::Range(1, kMaxSweepWorkers));
  sub.add_option("--shard", opt->shard,
                 "run only shard I of N (I from 0): the episodes at positions I, I+N, ... of the "
                 "sweep's canonical order")
      ->capture_default_str();
  opt->plugins.addTo(sub);
  opt->user_code.addTo(sub);
  sub.add_flag("--slurm", opt->slurm,
               "write OUT/sweep.sbatch (a Slurm job array, one task per shard) instead of "
               "running");
  sub.add_option("--slurm-shards", opt->slurm_shards,
                 "array tasks (default 10, at most one per episode)")
      ->check(CLI::Range(1, 100000));
  CLI::Option* cpus = sub.add_option("--slurm-cpus", opt->slurm_def.cpus_per_task,
                                     "CPUs per task (the task's --workers)")
                          ->capture_default_str()
                          ->check(CLI::Range(1, 1024));
  CLI::Option* mem =
      sub.add_option("--slurm-mem", opt->slurm_def.mem, "memory per task")->capture_default_str();
  CLI::Option* time_limit =
      sub.add_option("--slurm-time", opt->slurm_def.time, "time limit per task")
          ->capture_default_str();
  CLI::Option* partition = sub.add_option("--slurm-partition", opt->slurm_def.partition,
                                          "partition (default: the cluster's)");
  CLI::Option* account =
      sub.add_option("--slurm-account", opt->slurm_def.account, "account to charge");
  sub.add_flag("--missing", opt->missing,
               "with --slurm: find the shards whose tables lack episodes (tasks that died) and "
               "submit only those array tasks again (sbatch --array=LIST), asking for what the "
               "first submission asked unless --slurm-* options say otherwise");
  sub.add_flag("--wait", opt->wait,
               "with --slurm --missing: wait until the submitted tasks end (sbatch --wait)");
  CLI::Option* max_parallel =
      sub.add_option("--slurm-max-parallel", opt->slurm_max_parallel,
                     "at most this many tasks at once (the array's %K throttle)")
          ->check(CLI::Range(1, 100000));
  cli::addReportFileOption(sub, "--junit", opt->junit,
                           "also write a JUnit XML report: one test case per episode (of the "
                           "shard), one suite per world x planner x realism (docs/ci.md)");
  // --progress is every command's (main.cpp): not a terminal, the line comes every 10 s.
  const std::vector<const CLI::Option*> request = {cpus,      mem,     time_limit,
                                                   partition, account, max_parallel};
  return [opt, request](const OutputOptions& output) {
    if (!opt->list && opt->out.empty()) throw Error("--out is required (or --list)");
    opt->progress = output.progress;
    for (const CLI::Option* option : request) {
      if (option->count() > 0) opt->slurm_given.insert(option->get_name());
    }
    return runSweepCommand(*opt);
  };
}

}  // namespace parksim::app
