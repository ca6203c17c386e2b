#include "parksim/sim/episode/ContactEvents.h"

namespace parksim {

ContactEventMerger::ContactEventMerger(std::size_t obstacle_count, long merge_steps)
    : merge_steps_(merge_steps), last_touch_(obstacle_count, -1) {}

void ContactEventMerger::add(long k, double t_s, const std::vector<int>& touching,
                             const std::vector<Obstacle>& obstacles) {
  for (int index : touching) {
    const auto i = static_cast<std::size_t>(index);
    long& last = last_touch_[i];
    if (last < 0 || k - last > merge_steps_) events_.push_back({t_s, index, obstacles[i].name});
    last = k;
  }
}

}  // namespace parksim
