#pragma once
// Footprint queries against a scenario's static obstacles, answered by Bullet: a broadphase
// (btDbvtBroadphase) picks the obstacles whose bounding boxes meet the footprint's, and the
// box-box detector decides each box exactly; circles and convex polygons are decided exactly
// in double by core's separation (Geometry.h), and compound obstacles (non-convex polygons,
// maps) part by part the same way, on the parts their compound shape's tree finds near. Obstacles
// no higher than the robot's ground clearance are left out (blocksRobot). Bullet stays behind this
// header so that the planner and the app never include it.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/Scenario.h"

namespace parksim {

/// Every obstacle of a Scenario as a box in a btCollisionWorld, and the ego robot's footprint
/// as the query shape. Obstacles stand on the ground (z from 0 to their height); the footprint
/// is a box of the robot's height standing on the same ground, so only the plane decides.
///
/// Not thread-safe: queries reuse one scratch shape and candidate buffer and bump counters,
/// so a planner that checks in parallel needs one world per thread.
class BulletCollisionWorld final : public FootprintChecker {
 public:
  /// Query counters, for statistics.
  struct Stats {
    std::uint64_t free_queries = 0;         ///< isFree calls
    std::uint64_t overlapping_queries = 0;  ///< overlapping calls
    std::uint64_t clearance_queries = 0;    ///< clearance calls
    std::uint64_t box_box_tests = 0;        ///< narrowphase box-box tests run by all queries
    std::uint64_t shape_tests = 0;          ///< exact circle and polygon tests run by all queries
  };

  /// Copies the obstacles and the robot; keeps no reference to `scenario`. Throws Error when
  /// an obstacle or the robot has a non-positive or non-finite size.
  explicit BulletCollisionWorld(const Scenario& scenario);
  ~BulletCollisionWorld() override;

  BulletCollisionWorld(const BulletCollisionWorld&) = delete;
  BulletCollisionWorld& operator=(const BulletCollisionWorld&) = delete;
  /// A moved-from world may only be destroyed or assigned to.
  BulletCollisionWorld(BulletCollisionWorld&&) noexcept;
  BulletCollisionWorld& operator=(BulletCollisionWorld&&) noexcept;

  /// True when footprintAt(robot, pose, margin_m) penetrates no obstacle; touching is free.
  /// Allocates nothing. Throws Error when margin_m is negative or not finite, or the pose is
  /// not finite (the same holds for overlapping() and clearance()).
  ///
  /// Bullet computes in float; the footprint is handed to it relative to each candidate
  /// obstacle, which keeps the answer right for poses at least 1e-7 m from touching (measured
  /// on the study's lot; poses closer than that may be classified either way).
  bool isFree(const Pose2& pose, double margin_m = 0.0) const override;

  /// Names of the obstacles the footprint penetrates, in scenario order (empty when free).
  std::vector<std::string> overlapping(const Pose2& pose, double margin_m = 0.0) const override;

  /// Distance from the footprint (no margin) to the nearest obstacle in the plane, m: 0 when
  /// touching or overlapping, +infinity when there are no obstacles. Computed exactly in double
  /// on the broadphase's candidates within a growing search radius. Allocates nothing.
  double clearance(const Pose2& pose) const;

  /// Obstacles the robot can hit (those that block it), not all of the scenario's.
  std::size_t obstacleCount() const;

  Stats stats() const;
  void resetStats();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
