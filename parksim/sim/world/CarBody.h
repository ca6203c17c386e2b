#pragma once
// A car in the dynamics world (RobotDef::isCar, docs/cars.md): a btMultiBody whose base is the
// chassis box (exactly the planner's footprint, from the ground clearance to the car's height),
// two driven rear sphere wheels on velocity motors or joint torques (as the differential robot's,
// RobotBody.h), and two front sphere wheels that roll freely on knuckles turned about vertical
// revolute joints through their centres by position servos. Internal to sim/; Bullet's types are
// only declared here.
//
// Steering: setSteerTarget gives the bicycle angle; before every step the set-point moves toward
// it at most RobotDef::max_steer_rate_radps x dt, within +-max_steer_rad (the rack's stops), and
// each knuckle's servo follows its own Ackermann angle of the set-point (Ackermann.h). The
// measured steering (RobotState::steer_rad) is the bicycle angle of the knuckles' joint angles.
// A sphere turned about a vertical axis through its centre touches the ground at the same point,
// so steering meets no scrub torque, even standing still.
//
// Four wheels on the ground: each wheel's contact is a critically damped spring (CarModelDef),
// so each carries its share of the weight. Wheels touch the ground only, the chassis obstacles
// only (CollisionGroups.h). The car's mass matrix changes with its steering angle, so its rows
// are Bullet's own (MultiBodyInverseMass does not cover it).

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Ackermann.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "parksim/sim/world/EgoBody.h"

class btCollisionObject;
class btCollisionShape;
class btMultiBody;
class btMultiBodyDynamicsWorld;
class btMultiBodyConstraint;
class btMultiBodyJointMotor;
class btMultiBodyLinkCollider;

namespace parksim {

class CarBody final : public EgoBody {
 public:
  /// Link indices of the multibody: the driven rear wheels first, at the differential robot's
  /// indices, then each front knuckle followed by its wheel.
  static constexpr int kRearLeft = 0;
  static constexpr int kRearRight = 1;
  static constexpr int kLeftKnuckle = 2;
  static constexpr int kFrontLeft = 3;
  static constexpr int kRightKnuckle = 4;
  static constexpr int kFrontRight = 5;

  /// Builds the car as `model.body` says (true rear radii and track, drive) with its reference
  /// point at `start` (lot frame), wheels straight, and adds it to `world`, whose frame has its
  /// origin at `origin` in the lot frame. Keeps a reference to `world`.
  CarBody(btMultiBodyDynamicsWorld& world, const RobotDef& car, const PhysicsDef& physics,
          const SimModelDef& model, const Pose2& start, const Eigen::Vector2d& origin);
  ~CarBody() override;

  CarBody(const CarBody&) = delete;
  CarBody& operator=(const CarBody&) = delete;

  void setWheelTargets(const WheelSpeeds& targets) override;
  void addWheelTorques(const WheelSpeeds& torques_nm) override;
  void setSteerTarget(double steer_rad) override;
  void beforeStep(double dt_s) override;

  RobotState state() const override;
  const btCollisionObject* chassis() const override;

  double leftRadius() const override { return left_radius_; }
  double rightRadius() const override { return right_radius_; }
  double track() const override { return geometry_.wheel_base_m; }

 private:
  void addColliders(btCollisionShape* chassis_shape, btCollisionShape* rear_left,
                    btCollisionShape* rear_right, btCollisionShape* front);
  void addMotors();
  btCollisionShape* own(std::unique_ptr<btCollisionShape> shape);

  btMultiBodyDynamicsWorld& world_;
  RobotDef robot_;
  RobotDef geometry_;  // the car as built: true track (the steering linkage's Ackermann)
  PhysicsDef physics_;
  SimModelDef model_;
  Eigen::Vector2d origin_;
  double left_radius_;
  double right_radius_;
  // Chassis centre relative to the reference point, in the chassis frame, m.
  double chassis_dx_ = 0.0;
  double chassis_z_ = 0.0;
  double target_rad_ = 0.0;    // bicycle angle asked for
  double setpoint_rad_ = 0.0;  // bicycle angle the servos follow (rate-limited)

  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::unique_ptr<btMultiBody> body_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;   // chassis, four wheels
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> wheel_motors_;  // rear left, rear right
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> steer_motors_;  // left, right knuckle
};

}  // namespace parksim
