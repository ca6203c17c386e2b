#include "parksim/pipeline/RealisationsJUnit.h"

#include "parksim/core/NumberFormat.h"

namespace parksim {

namespace {

std::vector<JUnitProperty> episodeProperties(const EpisodeOutcome& out, std::uint64_t noise_seed) {
  const PlanSetup& p = out.plan_setup;
  std::vector<JUnitProperty> props = {{"world", out.world->scenario.name},
                                      {"world_file", out.world->scenario.source_path},
                                      {"planner", p.planner},
                                      {"steering", toString(p.steering_kind)},
                                      {"seed", std::to_string(p.search.seed)},
                                      {"max_iterations", std::to_string(p.search.max_iterations)},
                                      {"timing", toString(p.timing)},
                                      {"tracking", toString(out.execution.tracking)},
                                      {"realism", out.execution.realism.name},
                                      {"noise_seed", std::to_string(noise_seed)}};
  return props;
}

// The numbers behind a verdict, for the failure's text.
std::string metricsText(const EpisodeMetrics& m) {
  return "max tracking error " + formatFixed(m.max_pos_err_m * 1e3, 3) + " mm, final " +
         formatFixed(m.final_pos_err_m * 1e3, 3) + " mm; goal error " +
         formatFixed(m.goal_pos_err_m * 1e3, 3) + " mm / " +
         formatFixed(m.goal_heading_err_deg, 3) + " deg (" +
         (m.goal_reached ? "reached" : "not reached") + "); " + std::to_string(m.contacts) +
         " contact events";
}

}  // namespace

JUnitReport realisationsJUnit(const EpisodeOutcome& out) {
  const std::string realism = out.driven() ? out.execution.realism.name : "-";
  JUnitSuite suite;
  suite.name = out.world->scenario.name + " / " + out.plan_setup.planner + " / " + realism;
  suite.properties = {{"verdict", toString(out.verdict.status)},
                      {"realisations", std::to_string(out.realisations.size())},
                      {"realisations_met", std::to_string(out.realisationsMet())}};
  if (out.plan && out.plan->solved()) {
    suite.properties.push_back({"plan_time_s", formatShortest(out.plan->stats.times.total_s)});
  }
  if (!out.driven()) {
    JUnitCase c;
    c.name = "plan";
    c.classname = suite.name;
    if (out.plan) c.time_s = out.plan->stats.times.total_s;
    c.properties = episodeProperties(out, out.execution.noise_seed);
    c.properties.push_back({"status", toString(out.verdict.status)});
    if (!out.verdict.met()) {
      c.failure =
          JUnitFailure{out.verdict.reason, toString(out.verdict.status), out.verdict.reason};
    }
    suite.cases.push_back(std::move(c));
  }
  for (const RealisationOutcome& r : out.realisations) {
    JUnitCase c;
    c.name = "noise_seed=" + std::to_string(r.noise_seed);
    c.classname = suite.name;
    c.time_s = r.metrics.wall_time_s;
    c.properties = episodeProperties(out, r.noise_seed);
    c.properties.push_back({"status", toString(r.verdict.status)});
    if (!r.verdict.met()) {
      c.failure = JUnitFailure{r.verdict.reason, toString(r.verdict.status),
                               r.verdict.reason + "\n" + metricsText(r.metrics)};
    }
    suite.cases.push_back(std::move(c));
  }
  return {"parksim run " + out.world->scenario.name, {std::move(suite)}};
}

}  // namespace parksim
