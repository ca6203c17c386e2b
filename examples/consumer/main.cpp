// Plans a world's parking manoeuvre and drives it in the simulation, using parksim as an
// installed library. Usage: park WORLD [SEED]

#include <cstdio>
#include <cstdlib>
#include <string>

#include <memory>

#include <parksim/core/io/Error.h>
#include <parksim/pipeline/EpisodePipeline.h>
#include <parksim/scenario/world/World.h>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: park WORLD [SEED]\n");
    return 2;
  }
  try {
    // One call: plan, drive, judge, with parksim's defaults (those of `parksim run`).
    parksim::EpisodeRequest request;
    request.world = std::make_shared<const parksim::World>(parksim::loadWorld(argv[1]));
    if (argc > 2) request.plan.search.seed = std::strtoull(argv[2], nullptr, 10);
    const parksim::EpisodeOutcome outcome = parksim::runEpisodePipeline(request);
    if (!outcome.driven()) {
      std::fprintf(stderr, "park: %s\n", outcome.verdict.reason.c_str());
      return 1;
    }
    const parksim::EpisodeMetrics& m = outcome.episode.metrics;
    std::printf(
        "%s: planned %zu points (%.2f s), drove %ld steps; tracking error max %.3f mm, "
        "goal %.3f mm / %.3f deg, %s, %d contacts; verdict: %s\n",
        request.world->scenario.name.c_str(), outcome.trajectory.points.size(),
        outcome.trajectory.duration(), m.steps, m.max_pos_err_m * 1e3, m.goal_pos_err_m * 1e3,
        m.goal_heading_err_deg, m.goal_reached ? "goal reached" : "goal missed", m.contacts,
        parksim::toString(outcome.verdict.status));
    return outcome.verdict.met() ? 0 : 1;
  } catch (const parksim::Error& e) {
    std::fprintf(stderr, "park: %s\n", e.what());
    return 2;
  }
}
