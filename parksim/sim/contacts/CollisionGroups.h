#pragma once
// Which bodies of the dynamics world may touch which. Internal to sim/; Bullet's filter type
// is only declared here.
//
// Wheels and slider touch only the ground, and the chassis only obstacles: the 20 mm wheels
// reach 10 mm past the front edge, and letting them hit obstacles would make the robot's
// contact shape larger than the footprint the planner checks.

#include <memory>

class btOverlapFilterCallback;

namespace parksim {

/// Collision filter groups (Bullet's group and mask bits, set on both sides of every pair).
enum CollisionGroup : int {
  kGroundGroup = 1 << 0,
  kStaticGroup = 1 << 1,
  kParkedGroup = 1 << 2,
  kChassisGroup = 1 << 3,
  kWheelGroup = 1 << 4,
};
inline constexpr int kGroundMask = kWheelGroup | kParkedGroup;
inline constexpr int kStaticMask = kChassisGroup | kParkedGroup;
inline constexpr int kParkedMask = kGroundGroup | kStaticGroup | kParkedGroup | kChassisGroup;
inline constexpr int kChassisMask = kStaticGroup | kParkedGroup;
inline constexpr int kWheelMask = kGroundGroup;

/// User index of collision objects that are not obstacles; obstacles carry their scenario
/// index.
inline constexpr int kNotObstacle = -1;

/// The broadphase's pair filter: the groups and masks above, and no pair of two fixed
/// obstacles (walls, parked robots not yet woken). Those cannot move, so a pair of them is pure
/// cost, and parked robots may overlap each other (docs/world-format.md): with the masks
/// alone, Bullet would keep and visit every step a pair for every two of n overlapping parked
/// robots, n^2 / 2 of them (10,000 on one spot ran out of memory). A woken parked robot is
/// re-added and pairs with its neighbours as before.
std::unique_ptr<btOverlapFilterCallback> makeFixedObstaclePairFilter();

}  // namespace parksim
