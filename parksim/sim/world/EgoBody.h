#pragma once
// The ego robot's multibody as the dynamics world drives it: a differential drive (RobotBody.h)
// or a car (CarBody.h). Internal to sim/; Bullet's types are only declared here.

#include "parksim/core/model/DiffDrive.h"

class btCollisionObject;

namespace parksim {

struct RobotState;

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
