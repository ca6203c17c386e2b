// runEpisode (Episode.h): an episode run to its end, with an observer at a fixed rate of
// simulated time.

#include "parksim/core/io/Error.h"
#include "parksim/sim/episode/Episode.h"

#include <utility>

namespace parksim {

EpisodeResult runEpisode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def,
                         const EpisodeObserver& observer, double observer_period_s,
                         EpisodeController controller) {
  Episode episode(scenario, plan, def, {}, std::move(controller));
  if (observer) {
    if (!(observer_period_s > 0.0)) throw Error("execution: observer period must be positive");
    observer(episode.sample());
  }
  const double dt = episode.world().timeStep();
  long next_observation = 1;  // index of the next period boundary to report
  while (!episode.finished()) {
    episode.step();
    if (!observer) continue;
    const long k = episode.world().steps();
    const bool due = static_cast<double>(k) * dt >=
                     static_cast<double>(next_observation) * observer_period_s - 1e-9 * dt;
    if (due || episode.finished()) {
      observer(episode.sample());
      while (static_cast<double>(next_observation) * observer_period_s - 1e-9 * dt <=
             static_cast<double>(k) * dt) {
        ++next_observation;
      }
    }
  }
  return {episode.metrics(), episode.rows(), episode.poseSamples()};
}

}  // namespace parksim
