#pragma once
// The ego robot in the dynamics world: a btMultiBody whose base is the chassis box (exactly
// the planner's footprint, from the ground clearance to the robot's height), two revolute
// sphere wheels driven by velocity motors or joint torques, and fixed frictionless sphere
// sliders where it needs them to stay upright (RobotSupports.h: the study robot's one at the
// rear). Internal to sim/; Bullet's types are only declared here.
//
// Building it is RobotBody.cpp; reading its state back after a step is RobotBodyState.cpp.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "parksim/sim/world/EgoBody.h"

class btCollisionObject;
class btCollisionShape;
class btMultiBody;
class btMultiBodyDynamicsWorld;
class btMultiBodyJointMotor;
class btMultiBodyLinkCollider;

namespace parksim {

class KernelParts;

class RobotBody final : public EgoBody {
 public:
  /// Link indices of the multibody.
  static constexpr int kLeftWheel = 0;
  static constexpr int kRightWheel = 1;
  /// The first slider; a second one, when the robot has one at each end, follows it.
  static constexpr int kSupport = 2;

  /// Builds the robot as `model.body` says (true radii and track, drive) with its reference
  /// point at `start` (lot frame), and adds it to `world`, whose frame has its origin at
  /// `origin` in the lot frame. Keeps a reference to `world`. Its motors come from `kernel`
  /// (the world's), which must outlive it; the robot's mass matrix is constant in its base
  /// frame (sphere wheels turn about their axles, the sliders are fixed), as
  /// KernelParts::addRobot requires.
  RobotBody(btMultiBodyDynamicsWorld& world, const RobotDef& robot, const PhysicsDef& physics,
            const SimModelDef& model, const Pose2& start, const Eigen::Vector2d& origin,
            KernelParts& kernel);
  /// Removes the robot from the world.
  ~RobotBody() override;

  RobotBody(const RobotBody&) = delete;
  RobotBody& operator=(const RobotBody&) = delete;

  /// WheelDrive::kVelocityMotor: the motors' velocity targets, held until changed.
  void setWheelTargets(const WheelSpeeds& targets) override;
  /// WheelDrive::kTorque: joint torques for the next step (Bullet clears them after each).
  void addWheelTorques(const WheelSpeeds& torques_nm) override;

  /// The robot's state now (RobotBodyState.cpp).
  RobotState state() const override;

  const btCollisionObject* chassis() const override;

  /// True geometry (TrueRobotDef applied to the nominal robot), m.
  double leftRadius() const override { return left_radius_; }
  double rightRadius() const override { return right_radius_; }
  double track() const override { return track_; }

 private:
  void addColliders(btCollisionShape* chassis_shape, btCollisionShape* left_shape,
                    btCollisionShape* right_shape, btCollisionShape* support_shape, int supports);
  void addMotors(KernelParts& kernel);
  btCollisionShape* own(std::unique_ptr<btCollisionShape> shape);

  btMultiBodyDynamicsWorld& world_;
  RobotDef robot_;
  PhysicsDef physics_;
  SimModelDef model_;
  Eigen::Vector2d origin_;
  double left_radius_;
  double right_radius_;
  double track_;
  // Chassis centre relative to the reference point, in the chassis frame, m.
  double chassis_dx_ = 0.0;
  double chassis_z_ = 0.0;

  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::unique_ptr<btMultiBody> body_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;  // chassis, wheels, sliders
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors_;       // left, right
};

}  // namespace parksim
