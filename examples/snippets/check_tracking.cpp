// Asserts tracking tolerances the way a CI job would: on an episode run in-process and on the
// metrics.json of an earlier `parksim run`. The program behind docs/simulation.md's
// "Tolerances for your CI" example, built and run by the tests.
// Usage: check_tracking WORLD METRICS_JSON    (exit 0: both within the default tolerance)

#include <cstdio>
#include <string>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/pipeline/Verdict.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: check_tracking WORLD METRICS_JSON\n");
    return 2;
  }
  try {
    const parksim::Scenario scenario = parksim::loadScenario(argv[1]);
    const parksim::BulletCollisionWorld collision(scenario);
    const parksim::PlanResult plan = parksim::planScenario(scenario, collision, {});
    if (!plan.solved()) {
      std::fprintf(stderr, "check_tracking: unsolved: %s\n", plan.message.c_str());
      return 1;
    }
    const parksim::EpisodeResult result = parksim::runEpisode(scenario, plan.trajectory);
    const std::string metrics_path = argv[2];
    // [docs:tracking-tolerance]
    // on an episode run in-process
    const auto violations = parksim::checkTracking(parksim::TrackingTolerance{}, result.metrics);
    // on a file written by `parksim run`
    const auto file_violations = parksim::checkTrackingFile({}, metrics_path);
    // [docs:end]
    if (!violations.empty() || !file_violations.empty()) {
      std::fprintf(stderr, "check_tracking: in-process: %s; file: %s\n",
                   parksim::joinViolations(violations).c_str(),
                   parksim::joinViolations(file_violations).c_str());
      return 4;
    }
    std::printf("check_tracking: both within tolerance (max tracking error %.3f mm)\n",
                result.metrics.max_pos_err_m * 1e3);
    return 0;
  } catch (const parksim::Error& e) {
    std::fprintf(stderr, "check_tracking: %s\n", e.what());
    return 2;
  }
}
