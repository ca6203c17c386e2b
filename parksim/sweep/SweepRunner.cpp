#include "parksim/sweep/SweepRunner.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "parksim/core/Error.h"
#include "parksim/core/Provenance.h"

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

SweepProgress runSweep(const std::vector<SweepEpisode>& episodes, const SweepRunnerDef& def,
                       ResultsTable& table, const SweepProgressFn& progress) {
  if (def.workers < 1) throw Error("workers must be at least 1");
  const auto t0 = std::chrono::steady_clock::now();
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

  std::mutex mutex;
  std::condition_variable ready;
  std::deque<nlohmann::ordered_json> finished;
  std::exception_ptr error;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  int running = 0;

  EpisodeRunDef episode_def = def.episode;
  std::mutex film_mutex;
  episode_def.film_mutex = &film_mutex;

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
      for (const auto& [key, value] : def.provenance.items()) row[key] = value;
      const bool met = row.value("met_tolerance", false);
      table.append(row);
      ++p.done;
      ++p.ran;
      if (!met) ++p.failed;
      p.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (progress) progress(p);
    }
  } catch (...) {
    stop.store(true);
    for (std::thread& t : threads) t.join();
    throw;
  }
  for (std::thread& t : threads) t.join();
  table.sync();
  if (error) std::rethrow_exception(error);
  return p;
}

}  // namespace parksim
