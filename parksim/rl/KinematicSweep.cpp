#include "parksim/rl/KinematicSweep.h"

#include <algorithm>
#include <cmath>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/model/Geometry.h"

namespace parksim {

KinematicSweep::KinematicSweep(const Scenario& scenario, const ParkingTaskDef& def,
                               const BulletCollisionWorld& collision)
    : check_m_(def.kinematic_check_m),
      radius_m_(footprintRadius(scenario.robot)),
      collision_(collision) {
  for (std::size_t i = 0; i < scenario.obstacles.size(); ++i) {
    const Obstacle& o = scenario.obstacles[i];
    index_.emplace(o.name, static_cast<int>(i));
    obstacles_.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
  }
}

Pose2 KinematicSweep::move(const Pose2& from, const Twist& twist, double duration_s,
                           std::vector<int>& contacts) const {
  // A footprint point at distance r from the reference point moves at most |v| + |omega| r.
  const double travel =
      (std::abs(twist.v_mps) + std::abs(twist.omega_radps) * radius_m_) * duration_s;
  const long checks = std::max(1L, static_cast<long>(std::ceil(travel / check_m_)));
  Pose2 reached = from;
  for (long j = 1; j <= checks; ++j) {
    const double t = j == checks
                         ? duration_s
                         : duration_s * static_cast<double>(j) / static_cast<double>(checks);
    const Pose2 pose = integrateExact(from, twist, t);
    if (!collision_.isFree(pose)) {
      for (const std::string& name : collision_.overlapping(pose)) {
        contacts.push_back(index_.at(name));
      }
      std::sort(contacts.begin(), contacts.end());
      break;
    }
    reached = pose;
  }
  return reached;
}

}  // namespace parksim
