// The bounded CI version of the sweep scale benchmark (bench/sweep_scale.sh; issue 22, item 1):
// 2,000 short episodes through the real pipeline (Hybrid A*, open loop, bench/scale/tiny.yaml)
// on one worker, measured by counts, not by the clock: the C++ heap in use (every operator new
// and delete of this program, all threads, counted exactly) and the allocations made, sampled
// at row counts. After the first 1,000 rows the heap may grow by at most 200 bytes per row, and
// the allocations per row (the work an episode does, row writing included) must stay what they
// were: nothing in the sweep costs more per row as the table grows. Then resuming, merging and
// verifying the 2,000-row table are measured the same way: their heap is bounded per row too.

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <new>

#include <gtest/gtest.h>

#include "parksim/results/tables/ResultsTable.h"
#include "parksim/results/tables/TableVerify.h"
#include "parksim/sweep/run/SweepRunner.h"
#include "parksim/sweep/shards/Merge.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/SweepSpecReader.h"
#include "tests/sweep/SweepTestSupport.h"

namespace {

// This program's operator new and delete count calls and the bytes in use (malloc's usable
// size, the same on both sides).
std::atomic<long long> g_live_bytes{0};
std::atomic<long long> g_allocations{0};

}  // namespace

// Under AddressSanitizer the sanitizer owns operator new; the counts are then not taken.
#if !defined(PARKSIM_SANITIZED)
namespace {

void* allocate(std::size_t n) {
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  g_live_bytes += static_cast<long long>(malloc_usable_size(p));
  ++g_allocations;
  return p;
}

void release(void* p) noexcept {
  if (p == nullptr) return;
  g_live_bytes -= static_cast<long long>(malloc_usable_size(p));
  std::free(p);
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
constexpr bool kCounting = true;
#else
constexpr bool kCounting = false;
#endif

namespace parksim {
namespace {

constexpr std::size_t kRows = 2000;

struct Sample {
  std::size_t rows;
  long long live_bytes;
  long long allocations;
};

struct Flatness {
  double bytes_per_row = 0.0;  ///< heap growth per row over the second half (least squares)
  double early = 0.0;          ///< allocations per row, rows tenth..half
  double late = 0.0;           ///< and over the second half
};

// Runs `episodes` on one worker into DIR's table, sampling the heap twenty times.
Flatness runMeasured(const SweepSpec& spec, const std::vector<SweepEpisode>& episodes,
                     const std::string& dir) {
  const std::size_t rows = episodes.size();
  const std::size_t every = rows / 20;
  std::vector<Sample> samples;
  {
    TableExpectations expect;
    for (const SetAxis& axis : spec.set) expect.set_columns.push_back(axis.path);
    ResultsTable table(dir, expect);
    SweepRunnerDef def;
    def.workers = 1;
    def.episode.episodes_dir = dir + "/episodes";
    // The progress callback runs on the writer after each row.
    runSweep(episodes, def, table, [&](const SweepProgress& p) {
      if (p.done % every == 0 && p.done > 0) {
        samples.push_back({p.done, g_live_bytes.load(), g_allocations.load()});
      }
    });
  }
  EXPECT_EQ(samples.size(), 20u);
  const std::size_t half = rows / 2;
  double n = 0, mx = 0, my = 0;
  for (const Sample& s : samples) {
    if (s.rows < half) continue;
    n += 1;
    mx += static_cast<double>(s.rows);
    my += static_cast<double>(s.live_bytes);
  }
  mx /= n;
  my /= n;
  double sxy = 0, sxx = 0;
  for (const Sample& s : samples) {
    if (s.rows < half) continue;
    sxy += (static_cast<double>(s.rows) - mx) * (static_cast<double>(s.live_bytes) - my);
    sxx += (static_cast<double>(s.rows) - mx) * (static_cast<double>(s.rows) - mx);
  }
  const auto at = [&samples](std::size_t r) {
    for (const Sample& s : samples)
      if (s.rows == r) return s;
    return Sample{};
  };
  const std::size_t tenth = 2 * every;
  Flatness f;
  f.bytes_per_row = sxy / sxx;
  f.early = double(at(half).allocations - at(tenth).allocations) / double(half - tenth);
  f.late = double(at(rows).allocations - at(half).allocations) / double(rows - half);
  std::printf(
      "heap growth after %zu rows: %.1f bytes/row; allocations per row %.1f (rows %zu-%zu), "
      "%.1f (rows %zu-%zu), ratio %.4f\n",
      half, f.bytes_per_row, f.early, tenth, half, f.late, half, rows, f.late / f.early);
  return f;
}

TEST(SweepScale, HeapAndWorkPerRowStayFlatOverTwoThousandRows) {
  if (!kCounting) GTEST_SKIP() << "AddressSanitizer replaces operator new: nothing to count";
  const std::string dir = testing::scratchDir();
  const SweepSpec spec = parseSweepSpec(
      "format: parksim-sweep/1\nname: scale\nworlds: [" + testing::sourceDir() +
          "/bench/scale/tiny.yaml]\nplanners: hybrid-a-star\ntracking: open\nseeds: {from: 1, "
          "to: " +
          std::to_string(kRows) + "}\n",
      "scale.yaml", "");
  const std::vector<SweepWorld> worlds = loadSweepWorlds(spec);
  const std::vector<SweepEpisode> episodes = expandEpisodes(spec, worlds);
  ASSERT_EQ(episodes.size(), kRows);
  const Flatness f = runMeasured(spec, episodes, dir);
  EXPECT_LE(f.bytes_per_row, 200.0);
  EXPECT_NEAR(f.late / f.early, 1.0, 0.02);

  // Reading the whole table back: resume (open and check), merge and verify hold one row at a
  // time: their heap at the end of the read is independent of the rows but for the ids.
  const long long before = g_live_bytes.load();
  long long resume_peak = 0;
  {
    ResultsTable table(dir);
    EXPECT_EQ(table.done().size(), kRows);
    resume_peak = g_live_bytes.load() - before;
  }
  const MergeResult merged = mergeResults({dir});
  const long long merge_held = g_live_bytes.load() - before;
  writeMergedTable(dir + "/merged", merged);
  EXPECT_TRUE(verifyResults(dir).ok());
  std::printf("held after reading %zu rows: resume %lld bytes, merge %lld bytes\n", kRows,
              resume_peak, merge_held);
  // The ids (map nodes and strings) and merge's offsets: well under 1 KB a row (a parsed row
  // would be ~8 KB).
  EXPECT_LE(resume_peak, static_cast<long long>(kRows) * 300);
  EXPECT_LE(merge_held, static_cast<long long>(kRows) * 400);
}

// A sampled parameter study (set: values drawn per sample, each episode reading its world
// again with them): as flat. 1,000 rows.
TEST(SweepScale, ASampledStudyStaysFlatToo) {
  if (!kCounting) GTEST_SKIP() << "AddressSanitizer replaces operator new: nothing to count";
  const std::string dir = testing::scratchDir();
  const SweepSpec spec =
      parseSweepSpec("format: parksim-sweep/1\nname: sampled\nworlds: [" + testing::sourceDir() +
                         "/bench/scale/tiny.yaml]\nplanners: hybrid-a-star\ntracking: open\n"
                         "set:\n  robot.max_wheel_speed_radps: {uniform: [6, 12]}\n"
                         "  goal.position_tolerance: {uniform: [0.002, 0.004]}\n"
                         "samples: {count: 1000, seed: 1}\n",
                     "sampled.yaml", "");
  const std::vector<SweepEpisode> episodes = expandEpisodes(spec, loadSweepWorlds(spec));
  ASSERT_EQ(episodes.size(), 1000u);
  const Flatness f = runMeasured(spec, episodes, dir);
  EXPECT_LE(f.bytes_per_row, 200.0);
  EXPECT_NEAR(f.late / f.early, 1.0, 0.02);
}

}  // namespace
}  // namespace parksim
