#pragma once
// The robot's wheel motors: Bullet's btMultiBodyJointMotor (a velocity target reached within an
// impulse limit per step), whose solver row is set up from MultiBodyInverseMass when it covers
// the body, instead of Bullet's articulated-body pass per row. Internal to sim/; Bullet's types
// are only declared here.

#include <memory>

class btMultiBody;
class btMultiBodyJointMotor;

namespace parksim {

class MultiBodyInverseMass;

/// A velocity motor on revolute joint `link` of `body`, at most `max_impulse` (N m s) per step,
/// target 0, whose row comes from `inverse_mass` while it covers `body` (else Bullet's own row
/// setup). `inverse_mass` must outlive the motor.
std::unique_ptr<btMultiBodyJointMotor> makeWheelMotor(btMultiBody& body, int link,
                                                      double max_impulse,
                                                      MultiBodyInverseMass& inverse_mass);

}  // namespace parksim
