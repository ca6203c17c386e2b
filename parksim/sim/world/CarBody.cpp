#include "parksim/sim/world/CarBody.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/sim/contacts/CollisionGroups.h"
#include "parksim/sim/world/BulletFrames.h"

namespace parksim {

namespace {

btVector3 sphereInertia(double mass_kg, double radius_m) {
  const btScalar i = btScalar(0.4 * mass_kg * radius_m * radius_m);
  return {i, i, i};
}

btVector3 vec(double x, double y, double z) { return {btScalar(x), btScalar(y), btScalar(z)}; }

}  // namespace

CarBody::CarBody(btMultiBodyDynamicsWorld& world, const RobotDef& car, const PhysicsDef& physics,
                 const SimModelDef& model, const Pose2& start, const Eigen::Vector2d& origin)
    : world_(world),
      robot_(car),
      geometry_(car),
      physics_(physics),
      model_(model),
      origin_(origin),
      left_radius_(car.wheel_radius_m * model.body.left_radius_scale),
      right_radius_(car.wheel_radius_m * model.body.right_radius_scale) {
  geometry_.wheel_base_m = car.wheel_base_m * model.body.track_scale;
  const CarModelDef& def = model_.car;
  const double r = robot_.wheel_radius_m;
  const double half_track = 0.5 * geometry_.wheel_base_m;
  const double bottom = robot_.ground_clearance_m;
  const double top = robot_.height_m;
  chassis_dx_ = robot_.footprintCenterOffset();
  chassis_z_ = 0.5 * (bottom + top);

  btCollisionShape* chassis_shape = own(std::make_unique<btBoxShape>(
      vec(0.5 * robot_.length_m, 0.5 * robot_.width_m, 0.5 * (top - bottom))));
  btVector3 chassis_inertia;
  chassis_shape->calculateLocalInertia(btScalar(physics_.chassis_mass_kg), chassis_inertia);
  const double wheel_mass = physics_.wheel_mass_kg;
  btCollisionShape* front_shape = own(std::make_unique<btSphereShape>(btScalar(r)));
  btCollisionShape* left_shape = left_radius_ == r
                                     ? front_shape
                                     : own(std::make_unique<btSphereShape>(btScalar(left_radius_)));
  btCollisionShape* right_shape =
      right_radius_ == r ? front_shape
                         : own(std::make_unique<btSphereShape>(btScalar(right_radius_)));
  btVector3 left_inertia = sphereInertia(wheel_mass, left_radius_);
  btVector3 right_inertia = sphereInertia(wheel_mass, right_radius_);
  if (model_.body.wheel_axle_inertia_kgm2 > 0.0) {  // the axle is the link's y axis
    left_inertia.setY(btScalar(model_.body.wheel_axle_inertia_kgm2));
    right_inertia.setY(btScalar(model_.body.wheel_axle_inertia_kgm2));
  }
  const double knuckle_mass = def.knuckle_mass_fraction * wheel_mass;
  // The knuckle as a sphere of half the wheel's radius: only its inertia about the steering
  // axis matters, and with the wheel's it is what the steering servo turns.
  const btVector3 knuckle_inertia = sphereInertia(knuckle_mass, 0.5 * r);
  // Bullet gives a revolute joint whose inertia about its axis is below SIMD_EPSILON no
  // acceleration at all (RobotBody.cpp): refused rather than simulated standing still.
  const btScalar least = std::min({left_inertia.y(), right_inertia.y(), knuckle_inertia.z()});
  if (!(least >= SIMD_EPSILON) || !(knuckle_mass > 0.0)) {
    throw Error("simulation: a car wheel's or steering knuckle's inertia, " +
                formatGeneral(double(least), 3) + " kg m^2 (physics.wheel_mass_kg " +
                formatGeneral(wheel_mass) + " kg, robot.wheel_radius " + formatGeneral(r) +
                " m), is below Bullet's " + formatGeneral(double(SIMD_EPSILON), 3) +
                " kg m^2, under which a joint never turns");
  }

  body_ = std::make_unique<btMultiBody>(6, btScalar(physics_.chassis_mass_kg), chassis_inertia,
                                        /*fixedBase=*/false, /*canSleep=*/false);
  const btQuaternion no_rotation(0, 0, 0, 1);
  const btVector3 no_offset(0, 0, 0);
  // Axis +y (to the car's left): a positive joint speed rolls the contact point backwards, so
  // positive drives forward, as WheelSpeeds require. Axis +z: a positive steering angle turns
  // the wheel to the left, as the bicycle angle.
  const btVector3 axle(0, 1, 0);
  const btVector3 kingpin(0, 0, 1);
  const double rear_dx = -chassis_dx_;  // reference point relative to the chassis centre
  const double front_dx = robot_.axle_distance_m - chassis_dx_;
  body_->setupRevolute(kRearLeft, btScalar(wheel_mass), left_inertia, -1, no_rotation, axle,
                       vec(rear_dx, half_track, left_radius_ - chassis_z_), no_offset, true);
  body_->setupRevolute(kRearRight, btScalar(wheel_mass), right_inertia, -1, no_rotation, axle,
                       vec(rear_dx, -half_track, right_radius_ - chassis_z_), no_offset, true);
  const btVector3 front_inertia = sphereInertia(wheel_mass, r);
  for (const auto& [knuckle, wheel, side] :
       {std::tuple{kLeftKnuckle, kFrontLeft, 1.0}, std::tuple{kRightKnuckle, kFrontRight, -1.0}}) {
    body_->setupRevolute(knuckle, btScalar(knuckle_mass), knuckle_inertia, -1, no_rotation, kingpin,
                         vec(front_dx, side * half_track, r - chassis_z_), no_offset, true);
    body_->setupRevolute(wheel, btScalar(wheel_mass), front_inertia, knuckle, no_rotation, axle,
                         no_offset, no_offset, true);
  }
  body_->finalizeMultiDof();
  // btMultiBody damps by default (0.04); an undamped model is what the plan assumes.
  body_->setLinearDamping(0);
  body_->setAngularDamping(0);
  body_->setHasSelfCollision(false);

  // At rest each wheel's spring is compressed by its deflection: start there.
  const double total_mass = physics_.chassis_mass_kg + 4.0 * wheel_mass + 2.0 * knuckle_mass;
  const double deflection = def.tyre_deflection_per_radius * r;
  const double c = std::cos(start.theta);
  const double s = std::sin(start.theta);
  body_->setBaseWorldTransform(planarTransform(start.x - origin_.x() + chassis_dx_ * c,
                                               start.y - origin_.y() + chassis_dx_ * s,
                                               chassis_z_ - deflection, start.theta));
  world_.addMultiBody(body_.get());
  addColliders(chassis_shape, left_shape, right_shape, front_shape);
  const double stiffness = 0.25 * total_mass * physics_.gravity_mps2 / deflection;
  const double damping = 2.0 * def.tyre_damping_ratio * std::sqrt(stiffness * 0.25 * total_mass);
  for (std::size_t i = 1; i < colliders_.size(); ++i) {
    colliders_[i]->setContactStiffnessAndDamping(btScalar(stiffness), btScalar(damping));
  }

  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_v;
  body_->forwardKinematics(scratch_q, scratch_v);
  body_->updateCollisionObjectWorldTransforms(scratch_q, scratch_v);
  addMotors();
}

CarBody::~CarBody() {
  for (auto& motor : steer_motors_) world_.removeMultiBodyConstraint(motor.get());
  for (auto& motor : wheel_motors_) world_.removeMultiBodyConstraint(motor.get());
  for (auto& collider : colliders_) world_.removeCollisionObject(collider.get());
  world_.removeMultiBody(body_.get());
}

btCollisionShape* CarBody::own(std::unique_ptr<btCollisionShape> shape) {
  shapes_.push_back(std::move(shape));
  return shapes_.back().get();
}

// The chassis touches obstacles only, the wheels the ground only (CollisionGroups.h).
void CarBody::addColliders(btCollisionShape* chassis_shape, btCollisionShape* rear_left,
                           btCollisionShape* rear_right, btCollisionShape* front) {
  auto add = [&](int link, btCollisionShape* shape, double friction, int group, int mask) {
    addEgoCollider(world_, *body_, link, shape, friction, group, mask,
                   model_.wheel_contact_processing_m, colliders_);
  };
  add(-1, chassis_shape, physics_.obstacle_friction, kChassisGroup, kChassisMask);
  add(kRearLeft, rear_left, physics_.wheel_friction, kWheelGroup, kWheelMask);
  add(kRearRight, rear_right, physics_.wheel_friction, kWheelGroup, kWheelMask);
  add(kFrontLeft, front, physics_.wheel_friction, kWheelGroup, kWheelMask);
  add(kFrontRight, front, physics_.wheel_friction, kWheelGroup, kWheelMask);
}

// The rear wheels' motors as the differential robot's (RobotBody::addMotors): impulse limits
// are torque x dt; driven by torque, the "motor" is the drive train's Coulomb friction. The
// steering servos: a position target with a velocity feed-forward (beforeStep).
void CarBody::addMotors() {
  const double dt = physics_.time_step_s;
  const bool torque_drive = model_.body.drive == WheelDrive::kTorque;
  if (!torque_drive || model_.body.joint_friction_nm > 0.0) {
    const double max_impulse =
        (torque_drive ? model_.body.joint_friction_nm : physics_.max_wheel_torque_nm) * dt;
    for (int link : {kRearLeft, kRearRight}) {
      // Bullet's own motor rows: a car's mass matrix is not constant in its base frame (the
      // knuckles steer), so the transcription's (sim/bullet/WheelMotor.h) does not apply.
      wheel_motors_.push_back(std::make_unique<btMultiBodyJointMotor>(
          body_.get(), link, btScalar(0), btScalar(max_impulse)));
      world_.addMultiBodyConstraint(wheel_motors_.back().get());
    }
  }
  const double steer_torque = model_.car.max_steer_torque_nm > 0.0 ? model_.car.max_steer_torque_nm
                                                                   : physics_.max_wheel_torque_nm;
  for (int link : {kLeftKnuckle, kRightKnuckle}) {
    steer_motors_.push_back(std::make_unique<btMultiBodyJointMotor>(body_.get(), link, btScalar(0),
                                                                    btScalar(steer_torque * dt)));
    steer_motors_.back()->setPositionTarget(0, btScalar(model_.car.steer_position_gain));
    steer_motors_.back()->setVelocityTarget(0, 1);
    world_.addMultiBodyConstraint(steer_motors_.back().get());
  }
}

void CarBody::setWheelTargets(const WheelSpeeds& targets) {
  if (wheel_motors_.empty() || model_.body.drive != WheelDrive::kVelocityMotor) return;
  wheel_motors_[0]->setVelocityTarget(btScalar(targets.left_radps));
  wheel_motors_[1]->setVelocityTarget(btScalar(targets.right_radps));
}

void CarBody::addWheelTorques(const WheelSpeeds& torques_nm) {
  body_->addJointTorque(kRearLeft, btScalar(torques_nm.left_radps));
  body_->addJointTorque(kRearRight, btScalar(torques_nm.right_radps));
}

void CarBody::setSteerTarget(double steer_rad) {
  if (std::isfinite(steer_rad)) target_rad_ = steer_rad;
}

// Each servo's joint velocity target is v_d + kp (q_d - q) / dt (Bullet's joint motor with
// kd = 1, erp = 1): q_d the wheel's angle of the set-point at the step's start, v_d its rate over
// the step. On track (q = q_d) the wheel turns exactly to the next set-point's angle; an error
// shrinks by kp each step.
void CarBody::beforeStep(double dt_s) {
  const double limit = robot_.max_steer_rad;
  const double target = std::clamp(target_rad_, -limit, limit);
  const double max_change = robot_.max_steer_rate_radps * dt_s;
  const double next = setpoint_rad_ + std::clamp(target - setpoint_rad_, -max_change, max_change);
  const FrontWheelAngles from = ackermannAngles(geometry_, setpoint_rad_);
  const FrontWheelAngles to = ackermannAngles(geometry_, next);
  const double kp = model_.car.steer_position_gain;
  steer_motors_[0]->setPositionTarget(btScalar(from.left_rad), btScalar(kp));
  steer_motors_[0]->setVelocityTarget(btScalar((to.left_rad - from.left_rad) / dt_s), 1);
  steer_motors_[1]->setPositionTarget(btScalar(from.right_rad), btScalar(kp));
  steer_motors_[1]->setVelocityTarget(btScalar((to.right_rad - from.right_rad) / dt_s), 1);
  setpoint_rad_ = next;
}

RobotState CarBody::state() const {
  RobotState out = readAxleState(*body_,
                                 {chassis_dx_, chassis_z_, robot_.wheel_radius_m, kRearLeft,
                                  kRearRight, left_radius_, right_radius_, geometry_.wheel_base_m},
                                 origin_);
  out.steer_rad = bicycleAngle(geometry_, {double(body_->getJointPos(kLeftKnuckle)),
                                           double(body_->getJointPos(kRightKnuckle))});
  out.steer_setpoint_rad = setpoint_rad_;
  return out;
}

const btCollisionObject* CarBody::chassis() const { return colliders_.front().get(); }

}  // namespace parksim
