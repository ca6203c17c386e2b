#include "parksim/sim/world/RobotBody.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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
#include "parksim/sim/world/KernelParts.h"
#include "parksim/sim/world/RobotSupports.h"

namespace parksim {

RobotBody::RobotBody(btMultiBodyDynamicsWorld& world, const RobotDef& robot,
                     const PhysicsDef& physics, const SimModelDef& model, const Pose2& start,
                     const Eigen::Vector2d& origin, KernelParts& kernel)
    : world_(world),
      robot_(robot),
      physics_(physics),
      model_(model),
      origin_(origin),
      left_radius_(robot.wheel_radius_m * model.body.left_radius_scale),
      right_radius_(robot.wheel_radius_m * model.body.right_radius_scale),
      track_(robot.wheel_base_m * model.body.track_scale) {
  const double r = robot_.wheel_radius_m;
  const double half_track = 0.5 * track_;
  const double bottom = robot_.ground_clearance_m;
  const double top = robot_.height_m;
  chassis_dx_ = robot_.footprintCenterOffset();
  chassis_z_ = 0.5 * (bottom + top);

  btCollisionShape* chassis_shape = own(std::make_unique<btBoxShape>(
      btVector3(btScalar(0.5 * robot_.length_m), btScalar(0.5 * robot_.width_m),
                btScalar(0.5 * (top - bottom)))));
  btVector3 chassis_inertia;
  chassis_shape->calculateLocalInertia(btScalar(physics_.chassis_mass_kg), chassis_inertia);
  btCollisionShape* wheel_shape = own(std::make_unique<btSphereShape>(btScalar(r)));
  btVector3 wheel_inertia;
  wheel_shape->calculateLocalInertia(btScalar(physics_.wheel_mass_kg), wheel_inertia);
  // Wheels of another true radius: their own spheres, centres at their own height, so the
  // chassis rolls slightly, as a real robot with unequal wheels does.
  const bool exact_wheels = left_radius_ == r && right_radius_ == r;
  btCollisionShape* left_shape =
      exact_wheels ? wheel_shape : own(std::make_unique<btSphereShape>(btScalar(left_radius_)));
  btCollisionShape* right_shape =
      exact_wheels ? wheel_shape : own(std::make_unique<btSphereShape>(btScalar(right_radius_)));
  btVector3 left_inertia = wheel_inertia;
  btVector3 right_inertia = wheel_inertia;
  if (!exact_wheels) {
    left_shape->calculateLocalInertia(btScalar(physics_.wheel_mass_kg), left_inertia);
    right_shape->calculateLocalInertia(btScalar(physics_.wheel_mass_kg), right_inertia);
  }
  if (model_.body.wheel_axle_inertia_kgm2 > 0.0) {  // the axle is the link's y axis
    left_inertia.setY(btScalar(model_.body.wheel_axle_inertia_kgm2));
    right_inertia.setY(btScalar(model_.body.wheel_axle_inertia_kgm2));
  }
  // btMultiBody gives a revolute joint whose inertia about its axis is below SIMD_EPSILON
  // (single precision: 1.2e-7 kg m^2) no acceleration at all (computeAccelerations...: invD =
  // 0): such a wheel never turns, whatever its motor does. A 1 cm robot's 2 mm, 0.1 g wheels
  // are 1.6e-10. Refused rather than simulated standing still.
  const btScalar axle_inertia = std::min(left_inertia.y(), right_inertia.y());
  if (!(axle_inertia >= SIMD_EPSILON)) {
    throw Error("simulation: the wheels' axle inertia, " + formatGeneral(double(axle_inertia), 3) +
                " kg m^2 (physics.wheel_mass_kg " + formatGeneral(physics_.wheel_mass_kg) +
                " kg as a sphere of robot.wheel_radius " + formatGeneral(r) +
                " m), is below Bullet's " + formatGeneral(double(SIMD_EPSILON), 3) +
                " kg m^2, under which a wheel joint never turns: at this radius a wheel needs " +
                formatGeneral(double(SIMD_EPSILON) / (0.4 * r * r), 3) + " kg or more");
  }
  const RobotSupports supports = robotSupports(robot_, physics_, model_);
  btCollisionShape* support_shape =
      own(std::make_unique<btSphereShape>(btScalar(supports.radius_m)));
  btVector3 support_inertia;
  support_shape->calculateLocalInertia(btScalar(model_.support_mass_kg), support_inertia);
  // Slider positions from the reference point: the rear one first (the study robot's only one).
  std::vector<double> sliders;
  if (supports.rear) sliders.push_back(supports.rear_x_m);
  if (supports.front) sliders.push_back(supports.front_x_m);

  // The base is the chassis box, its frame at the box centre (its centre of mass).
  body_ = std::make_unique<btMultiBody>(kSupport + static_cast<int>(sliders.size()),
                                        btScalar(physics_.chassis_mass_kg), chassis_inertia,
                                        /*fixedBase=*/false, /*canSleep=*/false);
  const btQuaternion no_rotation(0, 0, 0, 1);
  const btVector3 no_offset(0, 0, 0);
  // Axis +y (to the robot's left): a positive joint speed rolls the contact point backwards,
  // so positive drives the robot forward, as WheelSpeeds require.
  const btVector3 axle(0, 1, 0);
  const double axle_dx = -chassis_dx_;  // reference point relative to the chassis centre
  const double axle_dz = r - chassis_z_;
  const double left_dz = exact_wheels ? axle_dz : left_radius_ - chassis_z_;
  const double right_dz = exact_wheels ? axle_dz : right_radius_ - chassis_z_;
  body_->setupRevolute(kLeftWheel, btScalar(physics_.wheel_mass_kg), left_inertia, -1, no_rotation,
                       axle, btVector3(btScalar(axle_dx), btScalar(half_track), btScalar(left_dz)),
                       no_offset, true);
  body_->setupRevolute(
      kRightWheel, btScalar(physics_.wheel_mass_kg), right_inertia, -1, no_rotation, axle,
      btVector3(btScalar(axle_dx), btScalar(-half_track), btScalar(right_dz)), no_offset, true);
  const double support_z = supports.radius_m - chassis_z_;
  for (std::size_t i = 0; i < sliders.size(); ++i) {
    const double support_x = sliders[i] - chassis_dx_;
    body_->setupFixed(kSupport + static_cast<int>(i), btScalar(model_.support_mass_kg),
                      support_inertia, -1, no_rotation,
                      btVector3(btScalar(support_x), 0, btScalar(support_z)), no_offset, true);
  }
  body_->finalizeMultiDof();
  // btMultiBody damps by default (0.04); an undamped model is what the plan assumes.
  body_->setLinearDamping(0);
  body_->setAngularDamping(0);
  body_->setHasSelfCollision(false);

  const double c = std::cos(start.theta);
  const double s = std::sin(start.theta);
  body_->setBaseWorldTransform(planarTransform(start.x - origin_.x() + chassis_dx_ * c,
                                               start.y - origin_.y() + chassis_dx_ * s, chassis_z_,
                                               start.theta));
  world_.addMultiBody(body_.get());
  addColliders(chassis_shape, left_shape, right_shape, support_shape,
               static_cast<int>(sliders.size()));
  if (supports.stiffness_npm > 0.0) {
    for (std::size_t i = 0; i < sliders.size(); ++i) {
      colliders_[3 + i]->setContactStiffnessAndDamping(btScalar(supports.stiffness_npm),
                                                       btScalar(supports.damping_nspm));
    }
  }

  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_v;
  body_->forwardKinematics(scratch_q, scratch_v);
  body_->updateCollisionObjectWorldTransforms(scratch_q, scratch_v);
  kernel.addRobot(*body_);
  addMotors(kernel);
}

RobotBody::~RobotBody() {
  for (auto& motor : motors_) world_.removeMultiBodyConstraint(motor.get());
  for (auto& collider : colliders_) world_.removeCollisionObject(collider.get());
  world_.removeMultiBody(body_.get());
}

btCollisionShape* RobotBody::own(std::unique_ptr<btCollisionShape> shape) {
  shapes_.push_back(std::move(shape));
  return shapes_.back().get();
}

// The chassis touches obstacles only, the wheels and the slider the ground only
// (CollisionGroups.h). Wheel and slider points above the ground are not solved
// (SimModelDef::wheel_contact_processing_m).
void RobotBody::addColliders(btCollisionShape* chassis_shape, btCollisionShape* left_shape,
                             btCollisionShape* right_shape, btCollisionShape* support_shape,
                             int supports) {
  auto add = [&](int link, btCollisionShape* shape, double friction, int group, int mask) {
    addEgoCollider(world_, *body_, link, shape, friction, group, mask,
                   model_.wheel_contact_processing_m, colliders_);
  };
  add(-1, chassis_shape, physics_.obstacle_friction, kChassisGroup, kChassisMask);
  add(kLeftWheel, left_shape, physics_.wheel_friction, kWheelGroup, kWheelMask);
  add(kRightWheel, right_shape, physics_.wheel_friction, kWheelGroup, kWheelMask);
  for (int i = 0; i < supports; ++i) {
    add(kSupport + i, support_shape, physics_.support_friction, kWheelGroup, kWheelMask);
  }
}

// Motor limits are impulses per step: torque x dt. Driven by torque, the "motor" is the drive
// train's Coulomb friction: a target of zero speed that at most that torque holds.
void RobotBody::addMotors(KernelParts& kernel) {
  const bool torque_drive = model_.body.drive == WheelDrive::kTorque;
  if (torque_drive && !(model_.body.joint_friction_nm > 0.0)) return;
  const double max_impulse =
      (torque_drive ? model_.body.joint_friction_nm : physics_.max_wheel_torque_nm) *
      physics_.time_step_s;
  for (int link : {kLeftWheel, kRightWheel}) {
    motors_.push_back(kernel.makeWheelMotor(*body_, link, max_impulse));
    world_.addMultiBodyConstraint(motors_.back().get());
  }
}

void RobotBody::setWheelTargets(const WheelSpeeds& targets) {
  if (model_.body.drive != WheelDrive::kVelocityMotor) return;
  motors_[kLeftWheel]->setVelocityTarget(btScalar(targets.left_radps));
  motors_[kRightWheel]->setVelocityTarget(btScalar(targets.right_radps));
}

void RobotBody::addWheelTorques(const WheelSpeeds& torques_nm) {
  body_->addJointTorque(kLeftWheel, btScalar(torques_nm.left_radps));
  body_->addJointTorque(kRightWheel, btScalar(torques_nm.right_radps));
}

const btCollisionObject* RobotBody::chassis() const { return colliders_.front().get(); }

}  // namespace parksim
