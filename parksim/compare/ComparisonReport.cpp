#include "parksim/compare/ComparisonReport.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"

namespace parksim {

namespace {

bool isRate(const MetricComparison& m) { return m.q < 0.0; }

std::string percent(double share, int decimals) {
  std::string s = share >= 0.0 ? "+" : "";
  s += formatFixed(100.0 * share, decimals);
  s += " %";
  return s;
}

std::string statistic(const MetricComparison& m, double value, int met, int n) {
  if (!m.tested) return "-";
  if (isRate(m)) return std::to_string(met) + "/" + std::to_string(n);
  return formatFixed(1e3 * value, 3) + " mm";
}

std::string change(const MetricComparison& m) {
  if (isRate(m)) {
    const double pp = 100.0 * (m.candidate - m.baseline);
    std::string s = pp >= 0.0 ? "+" : "";
    s += formatFixed(pp, 1);
    s += " pp";
    return s;
  }
  if (m.baseline <= 0.0) return "-";
  return percent(m.candidate / m.baseline - 1.0, 1);
}

std::string interval(const MetricComparison& m) {
  if (isRate(m) || !m.tested || !std::isfinite(m.ci_low)) return "";
  return percent(m.ci_low, 1) + " .. " + percent(m.ci_high, 1);
}

std::string pValue(double p) {
  if (p < 1e-4) return "<0.0001";
  return formatGeneral(p, 2);
}

std::string confidenceText(const CompareDef& def) {
  return formatGeneral(100.0 * def.confidence, 4) + " %";
}

// A Markdown table cell: no line breaks, no column separators, no control characters.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : escapeText(text)) {
    if (c == '|')
      out += "\\|";
    else
      out += c;
  }
  return out;
}

std::string verdict(const MetricComparison& m) {
  if (!m.tested) return "not tested: " + m.note;
  return m.regression ? "**regression**" : "ok";
}

// The group's name, then across columns what each side held: "head_in / * / world (planner:
// time-a-star vs example)".
std::string groupTitle(const GroupComparison& g) {
  std::string s = g.name();
  for (const AcrossValues& a : g.across) {
    s += &a == &g.across.front() ? " (" : "; ";
    s += a.column + ": " + a.baseline + " vs " + a.candidate;
    if (&a == &g.across.back()) s += ')';
  }
  return s;
}

// Which columns were compared across and what that means for groups and pairs.
std::string acrossSentence(const TableComparison& t) {
  if (t.across.empty()) return "";
  std::string s = "Compared across ";
  for (const std::string& column : t.across) {
    s += (&column == &t.across.front() ? "`" : ", `") + cell(column) + "`";
  }
  s += ": the tables may differ in ";
  s += t.across.size() == 1 ? "it" : "them";
  s += "; rows pair when every other parameter is equal";
  if (std::find(t.across.begin(), t.across.end(), "planner") != t.across.end()) {
    s += ", and a group's name shows the planner as `*`";
  }
  s += ".\n\n";
  return s;
}

}  // namespace

std::string metricLine(const MetricComparison& m, const CompareDef& def) {
  if (!m.tested) return m.name + ": not tested (" + m.note + ")";
  std::string s = m.name + ": " + statistic(m, m.baseline, m.baseline_met, m.baseline_n) + " -> " +
                  statistic(m, m.candidate, m.candidate_met, m.candidate_n) + " (" + change(m);
  if (!isRate(m)) s += ", " + confidenceText(def) + " interval " + interval(m);
  s += "), Holm-adjusted p " + pValue(m.p_adjusted);
  if (m.regression) s += " < " + formatGeneral(1.0 - def.confidence, 3) + ": regression";
  return s;
}

std::string comparisonMarkdown(const TableComparison& t, const CompareDef& def,
                               const ComparisonSources& sources) {
  std::string s = "## parksim compare: ";
  s += t.regression() ? "regression (" + std::to_string(t.regressions) + " of " +
                            std::to_string(t.tests) + " tests)\n\n"
                      : "no regression\n\n";
  s += "Baseline `" + cell(sources.baseline) + "` (" + std::to_string(sources.baseline_rows) +
       " episodes), candidate `" + cell(sources.candidate) + "` (" +
       std::to_string(sources.candidate_rows) + " episodes): " + std::to_string(t.tests) +
       " tests in " + std::to_string(t.groups.size()) + " groups at " + confidenceText(def) +
       " family-wise confidence (Holm), " + std::to_string(t.resamples) +
       " bootstrap resamples, seed " + std::to_string(def.seed) +
       ". A regression: an error quantile above the baseline's by more than " +
       formatGeneral(100.0 * def.max_increase, 4) + " % and " +
       formatGeneral(1e3 * def.min_increase_m, 4) + " mm, or a success rate significantly lower" +
       (def.max_success_drop > 0.0
            ? " by more than " + formatGeneral(100.0 * def.max_success_drop, 4) + " pp"
            : std::string()) +
       ".\n\n";
  s += acrossSentence(t);
  s += "| group | episodes | metric | baseline | candidate | change | " + confidenceText(def) +
       " interval | p (Holm) | verdict |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const GroupComparison& g : t.groups) {
    const std::string pairing = g.paired ? std::to_string(g.shared_ids) + " paired"
                                         : std::to_string(g.baseline_rows) + " / " +
                                               std::to_string(g.candidate_rows) + " unpaired";
    bool first = true;
    for (const MetricComparison& m : g.metrics) {
      s += "| " + (first ? cell(groupTitle(g)) : std::string()) + " | " + (first ? pairing : "") +
           " | " + m.name + " | " + statistic(m, m.baseline, m.baseline_met, m.baseline_n) + " | " +
           statistic(m, m.candidate, m.candidate_met, m.candidate_n) + " | " +
           (m.tested ? change(m) : "") + " | " + interval(m) + " | " +
           (m.tested ? pValue(m.p_adjusted) : "") + " | " + cell(verdict(m)) + " |\n";
      first = false;
    }
  }
  const auto list = [&](const char* what, const std::vector<std::string>& names) {
    if (names.empty()) return;
    s += '\n';
    s += what;
    s += " (not compared):";
    for (const std::string& n : names) {
      s += " `";
      s += cell(n);
      s += '`';
    }
    s += '\n';
  };
  list("Only in the baseline", t.only_baseline);
  list("Only in the candidate", t.only_candidate);
  return s;
}

JUnitReport comparisonJUnit(const TableComparison& t, const CompareDef& def) {
  JUnitReport r{"parksim compare", {}};
  for (const GroupComparison& g : t.groups) {
    JUnitSuite suite;
    suite.name = g.name();
    suite.properties = {{"pairing", g.paired ? "paired" : "unpaired"},
                        {"baseline_rows", std::to_string(g.baseline_rows)},
                        {"candidate_rows", std::to_string(g.candidate_rows)},
                        {"shared_ids", std::to_string(g.shared_ids)}};
    for (const AcrossValues& a : g.across) {
      suite.properties.push_back({"baseline." + a.column, a.baseline});
      suite.properties.push_back({"candidate." + a.column, a.candidate});
    }
    for (const MetricComparison& m : g.metrics) {
      JUnitCase c;
      c.name = m.name;
      c.classname = suite.name;
      c.system_out = metricLine(m, def);
      if (m.regression) {
        c.failure = JUnitFailure{metricLine(m, def), "regression", metricLine(m, def)};
      } else if (!m.tested) {
        c.skipped = m.note;
      }
      suite.cases.push_back(std::move(c));
    }
    r.suites.push_back(std::move(suite));
  }
  return r;
}

}  // namespace parksim
