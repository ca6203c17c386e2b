#include "parksim/compare/TableComparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "parksim/compare/Bootstrap.h"
#include "parksim/compare/ExactTest.h"
#include "parksim/compare/HolmCorrection.h"
#include "parksim/compare/RowPairing.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/stats/Quantile.h"
#include "parksim/report/Report.h"
#include "parksim/sweep/spec/EpisodeParams.h"

namespace parksim {

namespace {

using Json = nlohmann::ordered_json;
using GroupKey = RowGroupKey;
/// A group's rows by what they pair by (RowPairing::pairKey: the episode id by default).
using GroupRows = std::map<std::string, const Json*>;

struct MetricSpec {
  const char* name;
  const char* key;
  double q;
};

// The tests of every group, in report order.
constexpr MetricSpec kMetrics[] = {
    {"success rate", "met_tolerance", -1.0},
    {"max tracking error median", "max_pos_err_m", 0.5},
    {"max tracking error p95", "max_pos_err_m", 0.95},
    {"goal error median", "goal_pos_err_m", 0.5},
    {"goal error p95", "goal_pos_err_m", 0.95},
};

std::string textOf(const Json& row, const char* key, const char* fallback) {
  const auto it = row.find(key);
  return it != row.end() && it->is_string() ? it->get<std::string>() : fallback;
}

bool numberIn(const Json& row, const char* key, double& out) {
  const auto it = row.find(key);
  if (it == row.end() || !it->is_number()) return false;
  out = it->get<double>();
  return std::isfinite(out);
}

bool metIn(const Json& row) {
  const auto it = row.find("met_tolerance");
  return it != row.end() && it->is_boolean() && it->get<bool>();
}

std::map<GroupKey, GroupRows> groupRows(const std::vector<Json>& rows, const char* which,
                                        const RowPairing& pairing) {
  if (rows.empty()) throw Error(std::string(which) + ": the table has no rows");
  std::map<GroupKey, GroupRows> groups;
  std::set<std::string> seen;
  for (const Json& row : rows) {
    const std::string id = textOf(row, "episode_id", "");
    if (id.empty()) throw Error(std::string(which) + ": a row without episode_id");
    if (!seen.insert(id).second) {
      throw Error(std::string(which) + ": episode " + id +
                  " appears twice (merge the table first: parksim merge)");
    }
    const auto [it, added] = groups[pairing.groupKey(row)].emplace(pairing.pairKey(row), &row);
    if (!added) {
      throw Error(std::string(which) + ": episodes " + textOf(*it->second, "episode_id", "") +
                  " and " + id + " differ only in columns compared across (" +
                  joinNames(pairing.across()) + "): compare tables with one value of them");
    }
  }
  return groups;
}

// Every across column must be somewhere: a misspelt one would pair nothing differently.
void checkAcrossColumnsPresent(const RowPairing& pairing, const std::vector<Json>& baseline,
                               const std::vector<Json>& candidate) {
  for (const std::string& column : pairing.across()) {
    const auto has = [&](const Json& row) { return row.contains(column); };
    if (std::none_of(baseline.begin(), baseline.end(), has) &&
        std::none_of(candidate.begin(), candidate.end(), has)) {
      throw Error("across: neither table has a column " + column);
    }
  }
}

// The distinct values of `column` in a group's rows, sorted, ", "-separated.
std::string valuesIn(const GroupRows& rows, const std::string& column) {
  std::set<std::string> values;
  for (const auto& [key, row] : rows) values.insert(RowPairing::valueText(*row, column));
  return joinNames(std::vector<std::string>(values.begin(), values.end()));
}

// The generator of one test: its own stream, so groups and metrics do not shift each other's.
std::mt19937_64 testRng(std::uint64_t seed, const std::string& group, const MetricSpec& m) {
  const std::string tag = std::to_string(seed) + "|" + group + "|" + m.name;
  return std::mt19937_64(fnv1a64(tag));
}

void compareRate(const GroupRows& b, const GroupRows& c, bool paired, MetricComparison& out) {
  if (paired) {
    int worse = 0;
    int better = 0;
    for (const auto& [id, row] : b) {
      const bool before = metIn(*row);
      const bool after = metIn(*c.at(id));
      out.baseline_met += before ? 1 : 0;
      out.candidate_met += after ? 1 : 0;
      worse += before && !after ? 1 : 0;
      better += !before && after ? 1 : 0;
    }
    out.baseline_n = out.candidate_n = static_cast<int>(b.size());
    out.p = mcnemarWorsePValue(worse, better);
  } else {
    for (const auto& [id, row] : b) out.baseline_met += metIn(*row) ? 1 : 0;
    for (const auto& [id, row] : c) out.candidate_met += metIn(*row) ? 1 : 0;
    out.baseline_n = static_cast<int>(b.size());
    out.candidate_n = static_cast<int>(c.size());
    out.p = fisherLowerPValue(out.baseline_met, out.baseline_n, out.candidate_met, out.candidate_n);
  }
  out.baseline = out.baseline_n > 0 ? static_cast<double>(out.baseline_met) / out.baseline_n : 0.0;
  out.candidate =
      out.candidate_n > 0 ? static_cast<double>(out.candidate_met) / out.candidate_n : 0.0;
  out.ci_low = out.ci_high = std::numeric_limits<double>::quiet_NaN();
  out.tested = out.baseline_n > 0 && out.candidate_n > 0;
  if (!out.tested) out.note = "no episodes";
}

// The metric's values on each side: matched by id when paired.
void sampleValues(const GroupRows& b, const GroupRows& c, bool paired, const char* key,
                  std::vector<double>& vb, std::vector<double>& vc) {
  double x = 0.0;
  double y = 0.0;
  if (paired) {
    for (const auto& [id, row] : b) {
      if (numberIn(*row, key, x) && numberIn(*c.at(id), key, y)) {
        vb.push_back(x);
        vc.push_back(y);
      }
    }
    return;
  }
  for (const auto& [id, row] : b) {
    if (numberIn(*row, key, x)) vb.push_back(x);
  }
  for (const auto& [id, row] : c) {
    if (numberIn(*row, key, y)) vc.push_back(y);
  }
}

void compareQuantile(const GroupRows& b, const GroupRows& c, bool paired, const CompareDef& def,
                     int resamples, std::mt19937_64 rng, MetricComparison& out) {
  std::vector<double> vb;
  std::vector<double> vc;
  sampleValues(b, c, paired, out.key.c_str(), vb, vc);
  out.baseline_n = static_cast<int>(vb.size());
  out.candidate_n = static_cast<int>(vc.size());
  if (out.baseline_n < def.min_samples || out.candidate_n < def.min_samples) {
    out.note = std::to_string(std::min(out.baseline_n, out.candidate_n)) + " values, fewer than " +
               std::to_string(def.min_samples);
    return;
  }
  out.baseline = quantile7(vb, out.q);
  out.candidate = quantile7(vc, out.q);
  const std::vector<QuantilePair> reps = bootstrapQuantiles(vb, vc, out.q, paired, resamples, rng);
  std::vector<double> relative;
  relative.reserve(reps.size());
  int not_beyond = 0;
  for (const QuantilePair& r : reps) {
    const double bound =
        std::max((1.0 + def.max_increase) * r.baseline, r.baseline + def.min_increase_m);
    not_beyond += r.candidate - bound <= 0.0 ? 1 : 0;
    relative.push_back(r.candidate / std::max(r.baseline, def.min_increase_m) - 1.0);
  }
  const double tail = 0.5 * (1.0 - def.confidence);
  std::sort(relative.begin(), relative.end());
  out.ci_low = quantileSorted7(relative, tail);
  out.ci_high = quantileSorted7(relative, 1.0 - tail);
  out.p = (1.0 + not_beyond) / (1.0 + static_cast<double>(reps.size()));
  out.tested = true;
}

GroupComparison newGroup(const GroupKey& key, const GroupRows& b, const GroupRows& c,
                         const RowPairing& pairing) {
  GroupComparison g;
  std::tie(g.world, g.planner, g.realism) = key;
  g.baseline_rows = static_cast<int>(b.size());
  g.candidate_rows = static_cast<int>(c.size());
  for (const auto& [id, row] : b) g.shared_ids += c.count(id) > 0 ? 1 : 0;
  g.paired = g.shared_ids == g.baseline_rows && g.shared_ids == g.candidate_rows;
  for (const std::string& column : pairing.across()) {
    g.across.push_back({column, valuesIn(b, column), valuesIn(c, column)});
  }
  for (const MetricSpec& m : kMetrics) {
    MetricComparison mc;
    mc.name = m.name;
    mc.key = m.key;
    mc.q = m.q;
    g.metrics.push_back(mc);
  }
  return g;
}

// Holm over every tested metric; a regression is significant and, for the success rate, a
// drop beyond the margin.
void judge(TableComparison& t, const CompareDef& def) {
  std::vector<double> p;
  for (const GroupComparison& g : t.groups) {
    for (const MetricComparison& m : g.metrics) {
      if (m.tested) p.push_back(m.p);
    }
  }
  const std::vector<double> adjusted = holmAdjusted(p);
  const double alpha = 1.0 - def.confidence;
  std::size_t k = 0;
  for (GroupComparison& g : t.groups) {
    for (MetricComparison& m : g.metrics) {
      if (!m.tested) continue;
      m.p_adjusted = adjusted[k++];
      const bool beyond = m.q >= 0.0 || m.baseline - m.candidate > def.max_success_drop;
      m.regression = m.p_adjusted < alpha && beyond;
      t.regressions += m.regression ? 1 : 0;
    }
  }
  t.tests = static_cast<int>(p.size());
}

}  // namespace

std::string GroupComparison::name() const { return rowGroupName({world, planner, realism}); }

void checkCompareDef(const CompareDef& def) {
  const auto bad = [](const std::string& what) { throw Error(what); };
  if (!(def.confidence > 0.0 && def.confidence < 1.0)) bad("confidence: must be in (0, 1)");
  if (!(def.max_increase >= 0.0 && def.max_increase <= 10.0)) {
    bad("max_increase: must be in [0, 10]");
  }
  if (!(def.min_increase_m >= 0.0 && def.min_increase_m <= 1.0)) {
    bad("min_increase_m: must be in [0, 1] m");
  }
  if (!(def.max_success_drop >= 0.0 && def.max_success_drop <= 1.0)) {
    bad("max_success_drop: must be in [0, 1]");
  }
  if (def.resamples < 100 || def.resamples > 10000000) bad("resamples: must be in [100, 1e7]");
  if (def.min_samples < 2 || def.min_samples > 1000000) bad("min_samples: must be in [2, 1e6]");
  (void)RowPairing(def.across);  // throws at a column that cannot be compared across
}

TableComparison compareTables(const std::vector<Json>& baseline, const std::vector<Json>& candidate,
                              const CompareDef& def) {
  checkCompareDef(def);
  const RowPairing pairing(def.across);
  checkAcrossColumnsPresent(pairing, baseline, candidate);
  const std::map<GroupKey, GroupRows> b = groupRows(baseline, "baseline", pairing);
  const std::map<GroupKey, GroupRows> c = groupRows(candidate, "candidate", pairing);
  TableComparison t;
  t.across = pairing.across();
  for (const auto& [key, rows] : b) {
    if (c.count(key) == 0) t.only_baseline.push_back(rowGroupName(key));
  }
  for (const auto& [key, rows] : c) {
    if (b.count(key) == 0) t.only_candidate.push_back(rowGroupName(key));
  }
  std::vector<GroupKey> keys;
  for (const auto& [key, rows] : b) {
    if (c.count(key) > 0) keys.push_back(key);
  }
  if (keys.empty()) {
    throw Error("no world / planner / realism group is in both tables (baseline has " +
                std::to_string(b.size()) + ", candidate " + std::to_string(c.size()) +
                "): were they run from the same spec?" +
                (pairing.across().empty()
                     ? " (tables of two planners or controllers compare with --across)"
                     : ""));
  }
  // Enough replicates that the smallest p-value, 1 / (B + 1), passes Holm's correction over
  // every test the tables can hold.
  const double alpha = 1.0 - def.confidence;
  const double tests = static_cast<double>(keys.size() * std::size(kMetrics));
  t.resamples = static_cast<int>(
      std::min(1e7, std::max<double>(def.resamples, std::ceil(2.0 * tests / alpha))));
  for (const GroupKey& key : keys) {
    const GroupRows& gb = b.at(key);
    const GroupRows& gc = c.at(key);
    GroupComparison g = newGroup(key, gb, gc, pairing);
    for (MetricComparison& m : g.metrics) {
      const MetricSpec& spec = kMetrics[&m - g.metrics.data()];
      if (m.q < 0.0) {
        compareRate(gb, gc, g.paired, m);
      } else {
        compareQuantile(gb, gc, g.paired, def, t.resamples, testRng(def.seed, g.name(), spec), m);
      }
    }
    t.groups.push_back(std::move(g));
  }
  judge(t, def);
  return t;
}

}  // namespace parksim
