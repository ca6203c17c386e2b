#pragma once
// The robot's wheel motors: Bullet's btMultiBodyJointMotor (a velocity target reached within an
// impulse limit per step), whose solver row is set up from MultiBodyInverseMass when it covers
// the body, instead of Bullet's articulated-body pass per row. Internal to sim/; Bullet's types
// are only declared here.

#include <memory>

class btMultiBody;
class btMultiBodyConstraint;

namespace parksim {

class MultiBodyInverseMass;

/// A velocity motor on revolute joint `link` of `body`, at most `max_impulse` (N m s) per step,
/// target 0. `inverse_mass` (may be null: Bullet's own row setup) must outlive the motor.
std::unique_ptr<btMultiBodyConstraint> makeWheelMotor(btMultiBody& body, int link,
                                                      double max_impulse,
                                                      MultiBodyInverseMass* inverse_mass);

/// The motor's velocity target, rad/s (positive as the joint turns positive).
void setWheelMotorTarget(btMultiBodyConstraint& motor, double target_radps);

}  // namespace parksim
