#pragma once
// Where the simulated robot rests on the ground besides its two wheels: passive frictionless
// sliders (ball casters) on its centre line near the ends of its body. Bullet-free, so that docs
// and tests can ask where they go without building a world.
//
// A two-wheeled body pitches about its wheels' contact line. With its centre of mass a distance
// d ahead of (or behind) the axle and h above the ground, a horizontal acceleration a pitches it
// by m a h against gravity's m g d; the wheels' friction with the ground (coefficient mu, the
// product of the two, as Bullet combines them) gives it at most a = mu g. A rigid slider at the
// centre of mass' end alone therefore holds it, whatever the drive does, when |d| > mu h: a
// three-point stand, whose load statics shares between the wheels and the slider. Otherwise the
// robot gets a slider at each end, and both are sprung (a contact stiffness, critically
// damped): on four rigid points the load would be shared at random, the frictionless sliders
// taking it from the wheels, which then slip; a rigid stop above the ground instead lets the
// body rock between its ends, and each landing unloads the wheels. Sprung, the wheels carry
// the weight and the sliders only the pitching moment.
//
// The study's robot (axle 10 mm behind its front edge, 80 mm long) needs its rigid rear slider
// only: d = -25.3 mm, mu h = 24.9 mm. A robot with its axle under its middle, or behind it
// unless its centre of mass lies far enough ahead, gets sprung sliders at both ends; one whose
// centre of mass lies far ahead of its axle, a rigid front slider.

#include "parksim/core/model/Scenario.h"

namespace parksim {

struct SimModelDef;

/// The sliders of a robot. Positions are from the reference point along the heading, m.
struct RobotSupports {
  bool rear = false;   ///< a slider support_inset from the rear edge, forward
  bool front = false;  ///< a slider support_inset from the front edge, backward
  double rear_x_m = 0.0;
  double front_x_m = 0.0;
  double radius_m = 0.0;  ///< each slider's sphere, m (its lowest point on the ground)
  /// Sprung sliders (two of them): each contact's stiffness, N/m, and damping, N s/m; 0: rigid.
  double stiffness_npm = 0.0;
  double damping_nspm = 0.0;
  /// The whole robot's centre of mass at rest (chassis, wheels, and the slider at the centre of
  /// mass' end): ahead of the axle along the heading (negative: behind it), and above the
  /// ground, m.
  double com_ahead_m = 0.0;
  double com_height_m = 0.0;
  double friction = 0.0;  ///< mu: the wheels' friction with the ground (capped at Bullet's 10)
};

/// The sliders `model` puts under `robot` with `physics` (the rule above). Their radius, inset
/// and deflection are SimModelDef's (the study robot's), scaled with the robot's size
/// (RobotDef::sizeScale): the study's robot keeps exactly its 8 mm slider 10 mm from its rear
/// edge.
RobotSupports robotSupports(const RobotDef& robot, const PhysicsDef& physics,
                            const SimModelDef& model);

}  // namespace parksim
