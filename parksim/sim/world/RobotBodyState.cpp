// Reading the robot's state back from the multibody after a step (RobotBody.h).

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include "parksim/sim/world/BulletFrames.h"
#include "parksim/sim/world/RobotBody.h"

namespace parksim {

RobotState readAxleState(const btMultiBody& body, const DrivenAxle& axle,
                         const Eigen::Vector2d& origin) {
  const btTransform base = body.getBaseWorldTransform();
  const btVector3 ref_local(btScalar(-axle.chassis_dx_m), 0,
                            btScalar(axle.wheel_radius_m - axle.chassis_z_m));
  const btVector3 ref = base * ref_local;
  RobotState out;
  out.local_pose = {double(ref.x()), double(ref.y()), yawOf(base)};
  out.pose = {out.local_pose.x + origin.x(), out.local_pose.y + origin.y(), out.local_pose.theta};
  out.axle_height_m = double(ref.z());
  const btVector3 up = base.getBasis().getColumn(2);
  out.tilt_rad = std::acos(std::clamp(double(up.z()), -1.0, 1.0));
  const btVector3 omega = body.getBaseOmega();
  const btVector3 vel = body.getBaseVel() + omega.cross(ref - base.getOrigin());
  out.twist = {
      double(vel.x()) * std::cos(out.pose.theta) + double(vel.y()) * std::sin(out.pose.theta),
      double(omega.z())};
  out.wheels = {double(body.getJointVel(axle.left_link)),
                double(body.getJointVel(axle.right_link))};
  out.wheel_angles = {double(body.getJointPos(axle.left_link)),
                      double(body.getJointPos(axle.right_link))};
  const double yaw_rate = double(omega.z());
  out.slip_mps = {out.wheels.left_radps * axle.left_radius_m -
                      (out.twist.v_mps - 0.5 * axle.track_m * yaw_rate),
                  out.wheels.right_radps * axle.right_radius_m -
                      (out.twist.v_mps + 0.5 * axle.track_m * yaw_rate)};
  out.awake = body.isAwake();
  return out;
}

RobotState RobotBody::state() const {
  return readAxleState(*body_,
                       {chassis_dx_, chassis_z_, robot_.wheel_radius_m, kLeftWheel, kRightWheel,
                        left_radius_, right_radius_, track_},
                       origin_);
}

}  // namespace parksim
