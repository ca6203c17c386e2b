// Reading the robot's state back from the multibody after a step (RobotBody.h).

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include "parksim/sim/world/BulletFrames.h"
#include "parksim/sim/world/RobotBody.h"

namespace parksim {

RobotState RobotBody::state() const {
  const btTransform base = body_->getBaseWorldTransform();
  const btVector3 ref_local(btScalar(-chassis_dx_), 0,
                            btScalar(robot_.wheel_radius_m - chassis_z_));
  const btVector3 ref = base * ref_local;
  RobotState out;
  out.local_pose = {double(ref.x()), double(ref.y()), yawOf(base)};
  out.pose = {out.local_pose.x + origin_.x(), out.local_pose.y + origin_.y(), out.local_pose.theta};
  out.axle_height_m = double(ref.z());
  const btVector3 up = base.getBasis().getColumn(2);
  out.tilt_rad = std::acos(std::clamp(double(up.z()), -1.0, 1.0));
  const btVector3 omega = body_->getBaseOmega();
  const btVector3 vel = body_->getBaseVel() + omega.cross(ref - base.getOrigin());
  out.twist = {
      double(vel.x()) * std::cos(out.pose.theta) + double(vel.y()) * std::sin(out.pose.theta),
      double(omega.z())};
  out.wheels = {double(body_->getJointVel(kLeftWheel)), double(body_->getJointVel(kRightWheel))};
  out.wheel_angles = {double(body_->getJointPos(kLeftWheel)),
                      double(body_->getJointPos(kRightWheel))};
  const double yaw_rate = double(omega.z());
  out.slip_mps = {
      out.wheels.left_radps * left_radius_ - (out.twist.v_mps - 0.5 * track_ * yaw_rate),
      out.wheels.right_radps * right_radius_ - (out.twist.v_mps + 0.5 * track_ * yaw_rate)};
  out.awake = body_->isAwake();
  return out;
}

}  // namespace parksim
