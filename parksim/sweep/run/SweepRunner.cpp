#include "parksim/sweep/run/SweepRunner.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <set>
#include <thread>
#include <tuple>

#include "parksim/core/io/Error.h"
#include "parksim/core/system/Provenance.h"
#include "parksim/pipeline/EpisodeSettings.h"

namespace parksim {

nlohmann::ordered_json provenanceColumns() {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [key, value] : provenanceFields(buildProvenance())) {
    if (key == "git_dirty") {
      j[key] = value == "true";
    } else {
      j[key] = value;
    }
  }
  char host[256] = {};
  j["host"] = gethostname(host, sizeof host - 1) == 0 ? host : "unknown";
  return j;
}

void checkSweepRunnerDef(const SweepRunnerDef& def) {
  if (def.workers < 1 || def.workers > kMaxSweepWorkers) {
    throw Error("workers: must be in [1, " + std::to_string(kMaxSweepWorkers) + "], got " +
                std::to_string(def.workers));
  }
  checkUserCodeLimits(def.limits);
}

int defaultSweepWorkers() {
  return std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMaxSweepWorkers);
}

bool sweepRunsUserCode(const std::vector<SweepEpisode>& episodes) {
  // Asked once per planner, controller and tracking: a request reads its world again.
  std::set<std::tuple<const Components*, std::string, std::string, std::string>> asked;
  for (const SweepEpisode& e : episodes) {
    if (!asked.emplace(e.components.get(), e.params.planner, e.params.controller, e.params.tracking)
             .second) {
      continue;
    }
    if (runsUserCode(sweepEpisodeRequest(e))) return true;
  }
  return false;
}

namespace {

using Clock = std::chrono::steady_clock;

// The calling thread's side of a run: adds provenance, appends, counts, reports.
class RowSink {
 public:
  RowSink(const SweepRunnerDef& def, ResultsTable& table, const SweepProgressFn& progress,
          SweepProgress& p)
      : def_(def), table_(table), progress_(progress), p_(p) {}

  void append(nlohmann::ordered_json row) {
    for (const auto& [key, value] : def_.provenance.items()) row[key] = value;
    const bool met = row.value("met_tolerance", false);
    table_.append(row);
    ++p_.done;
    ++p_.ran;
    if (!met) ++p_.failed;
    p_.elapsed_s = std::chrono::duration<double>(Clock::now() - t0_).count();
    if (progress_) progress_(p_);
  }

 private:
  const SweepRunnerDef& def_;
  ResultsTable& table_;
  const SweepProgressFn& progress_;
  SweepProgress& p_;
  Clock::time_point t0_ = Clock::now();
};

// Returns a worker's exception (the rows before it are appended), or null.
std::exception_ptr runOnThreads(const std::vector<const SweepEpisode*>& todo,
                                const SweepRunnerDef& def, const EpisodeRunDef& episode_def,
                                RowSink& sink) {
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<nlohmann::ordered_json> finished;
  std::exception_ptr error;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  int running = 0;

  auto work = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= todo.size() || stop.load()) break;
      try {
        nlohmann::ordered_json row = runSweepEpisode(*todo[i], episode_def);
        const std::lock_guard<std::mutex> lock(mutex);
        finished.push_back(std::move(row));
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        stop.store(true);
      }
      ready.notify_one();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    --running;
    ready.notify_one();
  };

  const int n = static_cast<int>(std::min<std::size_t>(def.workers, todo.size()));
  std::vector<std::thread> threads;
  running = n;
  for (int k = 0; k < n; ++k) threads.emplace_back(work);

  try {
    for (;;) {
      std::unique_lock<std::mutex> lock(mutex);
      ready.wait(lock, [&] { return !finished.empty() || running == 0; });
      if (finished.empty()) break;
      nlohmann::ordered_json row = std::move(finished.front());
      finished.pop_front();
      lock.unlock();
      sink.append(std::move(row));
    }
  } catch (...) {
    stop.store(true);
    for (std::thread& t : threads) t.join();
    throw;
  }
  for (std::thread& t : threads) t.join();
  return error;
}

// Each worker a process (UserCodeIsolation.h) that runs episode after episode and sends back
// its row as JSON text: nlohmann writes a double's shortest round-trip form, so the row read
// back is the row the worker made.
// Returns parksim's own failure in a worker (the rows before it are appended), or null.
std::exception_ptr runInProcesses(const std::vector<const SweepEpisode*>& todo,
                                  const SweepRunnerDef& def, const EpisodeRunDef& episode_def,
                                  RowSink& sink) {
  const WatchedWorker::Work work = [&](std::uint64_t task, UserCodeWatch& watch) {
    return runSweepEpisode(*todo.at(task), episode_def, &watch).dump();
  };
  const std::size_t n = std::min<std::size_t>(def.workers, todo.size());
  // Every worker's input is closed before any worker is destroyed (WatchedWorker::closeInput):
  // a worker forked later holds the earlier ones' inputs open.
  struct Pool : std::vector<std::unique_ptr<WatchedWorker>> {
    ~Pool() {
      for (std::unique_ptr<WatchedWorker>& w : *this) w->closeInput();
    }
  } pool;
  for (std::size_t k = 0; k < n; ++k) {
    pool.push_back(std::make_unique<WatchedWorker>(work, def.limits, def.fork_hooks));
  }
  std::size_t next = 0;
  std::size_t busy = 0;
  std::string error;  // parksim's own failure: the sweep stops after the running episodes
  for (;;) {
    for (std::unique_ptr<WatchedWorker>& w : pool) {
      if (next >= todo.size() || !error.empty()) break;
      if (w->dead()) w = std::make_unique<WatchedWorker>(work, def.limits, def.fork_hooks);
      if (!w->idle()) continue;
      w->start(next++);
      ++busy;
    }
    if (busy == 0) break;
    std::vector<pollfd> fds;
    for (const std::unique_ptr<WatchedWorker>& w : pool) fds.push_back({w->fd(), POLLIN, 0});
    // Wakes for an answer, or every 50 ms to check the limits of the workers' user code.
    ::poll(fds.data(), fds.size(), 50);
    for (std::unique_ptr<WatchedWorker>& w : pool) {
      std::optional<WorkerResult> r = w->poll();
      if (!r) continue;
      --busy;
      const SweepEpisode& episode = *todo.at(r->task);
      if (r->answer) {
        sink.append(nlohmann::ordered_json::parse(*r->answer));
      } else if (r->user_failure) {
        sink.append(failedEpisodeRow(episode, userCodeVerdict(*r->user_failure)));
      } else if (error.empty()) {
        error = "episode " + episode.id + ": " + r->failure;
      }
    }
  }
  return error.empty() ? nullptr : std::make_exception_ptr(Error(error));
}

}  // namespace

SweepProgress runSweep(const std::vector<SweepEpisode>& episodes, const SweepRunnerDef& def,
                       ResultsTable& table, const SweepProgressFn& progress) {
  checkSweepRunnerDef(def);
  std::vector<const SweepEpisode*> todo;
  SweepProgress p;
  p.total = episodes.size();
  for (const SweepEpisode& e : episodes) {
    const auto it = table.done().find(e.id);
    if (it == table.done().end()) {
      todo.push_back(&e);
    } else {
      ++p.done;
      if (!it->second) ++p.failed;
    }
  }
  if (progress) progress(p);
  if (todo.empty()) return p;

  EpisodeRunDef episode_def = def.episode;
  episode_def.limits = def.limits;
  std::mutex film_mutex;
  episode_def.film_mutex = &film_mutex;
  RowSink sink(def, table, progress, p);
  const std::exception_ptr error = def.processes || sweepRunsUserCode(episodes)
                                       ? runInProcesses(todo, def, episode_def, sink)
                                       : runOnThreads(todo, def, episode_def, sink);
  table.sync();
  if (error) std::rethrow_exception(error);
  return p;
}

}  // namespace parksim
