// Synthetic results tables with known truth for `parksim compare`'s tests: rows of three worlds
// under 20 noise seeds each, their tracking and goal errors drawn from a spread modelled on the
// `lab` preset's measured one (README: head_in, 20 noise seeds, max tracking error median
// 1.72 mm, p95 1.86 mm; goal error median 0.061 mm, p95 0.158 mm), or one six times wider with
// exponential goal errors and a fifth of the episodes failing. Shared by TableComparisonTest.cpp
// (the decision's rules) and TableComparisonRatesTest.cpp (its power and false-alarm rates).
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "parksim/compare/ComparedTable.h"
#include "parksim/compare/TableComparison.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/spec/EpisodeParams.h"
#include "tests/support/TestPaths.h"

namespace parksim::synthetic {

using Json = nlohmann::ordered_json;

// A world's typical tracking error and how the realisations spread around it.
struct Spread {
  double tracking_sigma;  ///< of the log of the max tracking error
  bool wide_goal;         ///< exponential goal errors (else half-normal)
  double met_share;       ///< episodes that meet their tolerance
};

inline constexpr Spread kLab{0.05, false, 0.95};
inline constexpr Spread kWide{0.30, true, 0.80};

struct World {
  const char* name;
  double tracking_median_m;
};

inline constexpr World kWorlds[] = {
    {"head_in", 1.72e-3}, {"parallel", 0.95e-3}, {"tight_parallel", 2.6e-3}};

inline Json syntheticRow(const char* world, std::uint64_t noise_seed, const Spread& s,
                  std::mt19937_64& rng, double tracking_median_m) {
  EpisodeParams p;
  p.world = world;
  p.world_file = std::string("../") + world + ".yaml";
  p.realism = "lab";
  p.noise_seed = noise_seed;
  Json row;
  row["episode_id"] = episodeId(p);
  appendParamColumns(p, row);
  const bool met = std::uniform_real_distribution<double>(0.0, 1.0)(rng) < s.met_share;
  row["status"] = met ? "met" : "goal_missed";
  row["met_tolerance"] = met;
  row["failure"] = met ? "" : "ended 3.4 mm / 0.2 deg from the goal (tolerance 3 mm / 1.5 deg)";
  row["plan_status"] = "exact_solution";
  row["plan_solved"] = true;
  const double tracking =
      tracking_median_m * std::exp(std::normal_distribution<double>(0.0, s.tracking_sigma)(rng));
  row["max_pos_err_m"] = tracking;
  row["rms_pos_err_m"] = 0.35 * tracking;
  row["final_pos_err_m"] = 0.05 * tracking;
  const double goal = s.wide_goal ? std::exponential_distribution<double>(1.0 / 0.09e-3)(rng)
                                  : std::abs(std::normal_distribution<double>(0.0, 0.09e-3)(rng));
  row["goal_pos_err_m"] = goal;
  row["goal_reached"] = met;
  row["contacts"] = 0;
  row["episode_wall_s"] = 0.5;
  return row;
}

inline std::vector<Json> syntheticTable(std::uint64_t first_noise_seed, const Spread& s,
                                 std::mt19937_64& rng) {
  std::vector<Json> rows;
  for (const World& w : kWorlds) {
    for (std::uint64_t k = 0; k < 20; ++k) {
      rows.push_back(syntheticRow(w.name, first_noise_seed + k, s, rng, w.tracking_median_m));
    }
  }
  return rows;
}

// The table as `parksim compare` gets it: written by the sweep's writer, read by its reader.
// In a folder of the running test's own: ctest runs the tests in parallel processes.
inline std::vector<Json> throughTheWriter(const std::vector<Json>& rows, const std::string& name) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::filesystem::path dir =
      parksim::testing::testOutputDir("TableComparison." + test) / name;
  std::filesystem::remove_all(dir);
  writeResultsTable(dir.string(), rows);
  return readComparedTable(dir.string()).rows;
}

inline bool trackingFlagged(const TableComparison& t, const std::string& world) {
  for (const GroupComparison& g : t.groups) {
    if (g.world != world) continue;
    for (const MetricComparison& m : g.metrics) {
      if (m.key == "max_pos_err_m" && m.regression) return true;
    }
  }
  return false;
}

}  // namespace parksim::synthetic
