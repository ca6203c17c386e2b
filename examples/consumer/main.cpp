// Plans a world's parking manoeuvre and drives it in the simulation, using parksim as an
// installed library. Usage: park WORLD [SEED]

#include <cstdio>
#include <cstdlib>
#include <string>

#include <parksim/collision/BulletCollisionWorld.h>
#include <parksim/core/Error.h>
#include <parksim/planner/PlanScenario.h>
#include <parksim/scenario/ScenarioReader.h>
#include <parksim/sim/Episode.h>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: park WORLD [SEED]\n");
    return 2;
  }
  try {
    const parksim::Scenario scenario = parksim::loadScenario(argv[1]);
    parksim::PlanSetup setup;
    if (argc > 2) setup.planner.seed = std::strtoull(argv[2], nullptr, 10);
    const parksim::BulletCollisionWorld collision(scenario);
    const parksim::PlanResult plan = parksim::planScenario(scenario, collision, setup);
    if (!plan.solved()) {
      std::fprintf(stderr, "park: unsolved: %s\n", plan.message.c_str());
      return 1;
    }
    const parksim::EpisodeResult episode = parksim::runEpisode(scenario, plan.trajectory);
    const parksim::EpisodeMetrics& m = episode.metrics;
    std::printf(
        "%s: planned %zu points (%.2f s), drove %ld steps; tracking error max %.3f mm, "
        "goal %.3f mm / %.3f deg, %s, %d contacts\n",
        scenario.name.c_str(), plan.trajectory.points.size(), plan.trajectory.duration(), m.steps,
        m.max_pos_err_m * 1e3, m.goal_pos_err_m * 1e3, m.goal_heading_err_deg,
        m.goal_reached ? "goal reached" : "goal missed", m.contacts);
    return m.goal_reached && m.contacts == 0 ? 0 : 1;
  } catch (const parksim::Error& e) {
    std::fprintf(stderr, "park: %s\n", e.what());
    return 2;
  }
}
