#pragma once
// The scenario's obstacles as bodies of the dynamics world. Internal to sim/; Bullet's types
// are only declared here.
//
// Every obstacle enters as a fixed body (mass 0). Parked robots become bodies with mass when
// the ego robot's footprint comes within SimModelDef::parked_wake_distance_m (by an exact
// separating-axis gap), so the first contact is already between two bodies with mass and a
// push moves them; resting bodies with mass would cost more than the robot itself. Worlds with
// more than SimModelDef::parked_lazy_count parked robots insert each into Bullet only when the
// robot comes within about parked_insert_distance_m (ParkedRobotGrid), since Bullet loops over
// every object it holds at every step.

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "parksim/sim/world/ParkedRobotGrid.h"

class btCollisionShape;
class btMultiBodyDynamicsWorld;
class btRigidBody;
class btTransform;

namespace parksim {

/// Adds a fixed body (mass 0, no damping) to `world` with its bounding box computed once
/// (DynamicsWorld does not update fixed bodies' boxes per step); `user_index` identifies it
/// (an obstacle's scenario index, or kNotObstacle).
std::unique_ptr<btRigidBody> addFixedBody(btMultiBodyDynamicsWorld& world, btCollisionShape* shape,
                                          const btTransform& transform, double friction, int group,
                                          int mask, int user_index);

class ObstacleBodies {
 public:
  /// Inserts the obstacles into `world` in scenario order (lazy parked robots excepted), their
  /// shapes by kContactObstacleShapes (collision/ObstacleShape.h), in Bullet's frame whose
  /// origin is `origin` in the lot frame. Keeps a reference to `world`.
  ObstacleBodies(btMultiBodyDynamicsWorld& world, const std::vector<Obstacle>& obstacles,
                 const RobotDef& robot, const PhysicsDef& physics, const SimModelDef& model,
                 const Eigen::Vector2d& origin);
  /// Removes its bodies from the world.
  ~ObstacleBodies();

  ObstacleBodies(const ObstacleBodies&) = delete;
  ObstacleBodies& operator=(const ObstacleBodies&) = delete;

  /// Inserts the lazy parked robots near the ego robot at `ego_pose` (lot frame), then gives
  /// mass to every parked robot its footprint comes within parked_wake_distance_m of.
  /// Candidates come from the broadphase (the footprint's bounding box grown by the wake
  /// distance against every proxy's box), so far parked robots cost nothing per step.
  void wakeNear(const Pose2& ego_pose);

  /// Where obstacle i is, in Bullet's frame: its body's transform, or for a parked robot not
  /// inserted yet the transform it will get (the same floats).
  btTransform transform(std::size_t i) const;

  std::size_t size() const { return obstacles_.size(); }

  /// Parked robots that have become bodies with mass, in the order they did.
  const std::vector<int>& woken() const { return woken_; }

 private:
  btTransform placement(std::size_t i) const;
  void insert(std::size_t i);
  void insertNear(const Pose2& ego_pose);
  void wake(std::size_t i);

  btMultiBodyDynamicsWorld& world_;
  SimModelDef model_;
  std::vector<Obstacle> obstacles_;
  RobotDef robot_;
  double friction_;
  double default_parked_mass_kg_;
  Eigen::Vector2d origin_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;  // per obstacle; null: not inserted yet
  std::vector<int> candidates_;                       // scratch of wakeNear
  std::vector<int> woken_;
  // Lazy parked robots: the grid, and where it was last asked (it is asked again once the
  // robot has moved a quarter of a cell).
  std::optional<ParkedRobotGrid> grid_;
  std::optional<Eigen::Vector2d> last_query_;
};

}  // namespace parksim
