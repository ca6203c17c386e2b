#pragma once
// The ego robot's multibody as the dynamics world drives it: a differential drive (RobotBody.h)
// or a car (CarBody.h). Internal to sim/; Bullet's types are only declared here.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/model/DiffDrive.h"

class btCollisionObject;
class btCollisionShape;
class btMultiBody;
class btMultiBodyDynamicsWorld;
class btMultiBodyLinkCollider;

namespace parksim {

struct RobotState;

/// Where a body's driven axle is and how its two driven wheels turn (links `left_link` and
/// `right_link`, radii in m, `track_m` apart): what both bodies read back after a step
/// (RobotBodyState.cpp). The reference point is `chassis_dx_m` behind and `chassis_z_m` above
/// the base's origin less the wheel radius `wheel_radius_m`; `origin` is the world frame's
/// origin in the lot.
struct DrivenAxle {
  double chassis_dx_m = 0.0;
  double chassis_z_m = 0.0;
  double wheel_radius_m = 0.0;
  int left_link = 0;
  int right_link = 1;
  double left_radius_m = 0.0;
  double right_radius_m = 0.0;
  double track_m = 0.0;
};
RobotState readAxleState(const btMultiBody& body, const DrivenAxle& axle,
                         const Eigen::Vector2d& origin);

/// Makes `shape` the collider of `body`'s link `link` (-1: its base) with `friction`, in
/// collision `group` and `mask`, and adds it to `world`; a wheel link's contacts are processed
/// from `wheel_contact_processing_m` away. Both bodies build their colliders so
/// (EgoColliders.cpp); `colliders` keeps it alive.
void addEgoCollider(btMultiBodyDynamicsWorld& world, btMultiBody& body, int link,
                    btCollisionShape* shape, double friction, int group, int mask,
                    double wheel_contact_processing_m,
                    std::vector<std::unique_ptr<btMultiBodyLinkCollider>>& colliders);

class EgoBody {
 public:
  virtual ~EgoBody() = default;

  /// WheelDrive::kVelocityMotor: the driven wheels' velocity targets (a car's rear wheels),
  /// held until changed.
  virtual void setWheelTargets(const WheelSpeeds& targets) = 0;
  /// WheelDrive::kTorque: joint torques of the driven wheels for the next step.
  virtual void addWheelTorques(const WheelSpeeds& torques_nm) = 0;
  /// A car: the bicycle angle its steering turns to (rate-limited); others ignore it.
  virtual void setSteerTarget(double /*steer_rad*/) {}
  /// Called before every physics step of `dt_s` (a car's steering set-point moves).
  virtual void beforeStep(double /*dt_s*/) {}

  /// The robot's state now.
  virtual RobotState state() const = 0;
  virtual const btCollisionObject* chassis() const = 0;

  /// True geometry of the driven wheels (TrueRobotDef applied to the nominal robot), m.
  virtual double leftRadius() const = 0;
  virtual double rightRadius() const = 0;
  virtual double track() const = 0;
};

}  // namespace parksim
