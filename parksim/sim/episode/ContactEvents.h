#pragma once
// Contact events from the per-step list of obstacles touching the chassis: contact points
// flicker while the robot pushes something, so a body touching again within the merge time of
// its last touch continues the same event. Internal to sim/.

#include <cstddef>
#include <vector>

#include "parksim/core/model/Scenario.h"
#include "parksim/sim/episode/EpisodeMetrics.h"

namespace parksim {

class ContactEventMerger {
 public:
  /// `obstacle_count` obstacles; a touch more than `merge_steps` steps after the same
  /// obstacle's last touch starts a new event.
  ContactEventMerger(std::size_t obstacle_count, long merge_steps);

  /// The obstacles (scenario indices) touching the chassis at step `k`, time `t_s`; names
  /// from `obstacles`.
  void add(long k, double t_s, const std::vector<int>& touching,
           const std::vector<Obstacle>& obstacles);

  /// Every event so far, in the order they started.
  const std::vector<ContactEvent>& events() const { return events_; }

 private:
  long merge_steps_;
  std::vector<long> last_touch_;  // per obstacle: step of its last touch, -1 if never
  std::vector<ContactEvent> events_;
};

}  // namespace parksim
