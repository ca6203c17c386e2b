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

#include "parksim/results/ResultsTable.h"
#include "parksim/results/TableVerify.h"
#include "parksim/sweep/EpisodeExpansion.h"
#include "parksim/sweep/Merge.h"
#include "parksim/sweep/SweepRunner.h"
#include "parksim/sweep/SweepSpecReader.h"
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

  std::vector<Sample> samples;
  {
    ResultsTable table(dir);
    SweepRunnerDef def;
    def.workers = 1;
    def.episode.episodes_dir = dir + "/episodes";
    // The progress callback runs on the writer after each row: a sample every 100 rows.
    runSweep(episodes, def, table, [&samples](const SweepProgress& p) {
      if (p.done % 100 == 0 && p.done > 0) {
        samples.push_back({p.done, g_live_bytes.load(), g_allocations.load()});
      }
    });
  }
  ASSERT_EQ(samples.size(), kRows / 100);
  // Heap growth per row after the first 1,000 rows (least squares over the samples there).
  double n = 0, mx = 0, my = 0;
  for (const Sample& s : samples) {
    if (s.rows < 1000) continue;
    n += 1;
    mx += static_cast<double>(s.rows);
    my += static_cast<double>(s.live_bytes);
  }
  mx /= n;
  my /= n;
  double sxy = 0, sxx = 0;
  for (const Sample& s : samples) {
    if (s.rows < 1000) continue;
    sxy += (static_cast<double>(s.rows) - mx) * (static_cast<double>(s.live_bytes) - my);
    sxx += (static_cast<double>(s.rows) - mx) * (static_cast<double>(s.rows) - mx);
  }
  const double bytes_per_row = sxy / sxx;
  // Allocations per row, rows 200-1000 against rows 1000-2000.
  const auto at = [&samples](std::size_t rows) {
    for (const Sample& s : samples)
      if (s.rows == rows) return s;
    return Sample{};
  };
  const double early = double(at(1000).allocations - at(200).allocations) / 800.0;
  const double late = double(at(2000).allocations - at(1000).allocations) / 1000.0;
  std::printf(
      "heap growth after 1,000 rows: %.1f bytes/row; allocations per row %.1f (rows "
      "200-1000), %.1f (rows 1000-2000), ratio %.4f\n",
      bytes_per_row, early, late, late / early);
  EXPECT_LE(bytes_per_row, 200.0);
  EXPECT_NEAR(late / early, 1.0, 0.02);

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

}  // namespace
}  // namespace parksim
