#pragma once
// Definition of the differential-drive ego robot. Defaults are the study's robot.

namespace parksim {

/// The study robot's size: the longer side of its 80 x 85 mm footprint, m. What parksim tuned
/// for the study's robot and holds for a robot of any size (margins, motion-check steps, the
/// simulation's sliders, the film's camera) is the study's value times RobotDef::sizeScale().
inline constexpr double kStudyRobotSize_m = 0.085;
/// The study robot's top speed: 10 rad/s wheels of 20 mm radius, m/s.
inline constexpr double kStudyTopSpeed_mps = 10.0 * 0.020;

struct RobotDef {
  /// Footprint length along the heading, m.
  double length_m = 0.080;
  /// Footprint width across the heading, m.
  double width_m = 0.085;
  /// Distance from the reference point (axle middle) forward to the front edge, m.
  /// The body reaches length_m - front_overhang_m behind the reference point.
  double front_overhang_m = 0.010;
  /// Distance between the two wheels' contact points, m.
  double wheel_base_m = 0.085;
  /// Wheel radius, m.
  double wheel_radius_m = 0.020;
  /// Largest wheel angular speed magnitude, rad/s.
  double max_wheel_speed_radps = 10.0;
  /// Largest wheel angular acceleration magnitude, rad/s^2.
  double max_wheel_accel_radps2 = 40.0;
  /// Body height, used by physics and rendering, m.
  double height_m = 0.050;
  /// Height of the chassis' underside above the ground, m. Obstacles no higher than this pass
  /// under the robot (the planner ignores them; the simulated chassis clears them).
  double ground_clearance_m = 0.002;

  /// Offset of the footprint's centre from the reference point along the heading, m
  /// (negative: the centre lies behind the axle).
  double footprintCenterOffset() const { return front_overhang_m - 0.5 * length_m; }

  /// The robot's size: the longer side of its footprint, m.
  double size() const { return length_m > width_m ? length_m : width_m; }
  /// Its size in study robots (size() / kStudyRobotSize_m): exactly 1 for the study's robot, so
  /// a study value times it is that value to the bit.
  double sizeScale() const { return size() / kStudyRobotSize_m; }
  /// Top speed of the reference point, m/s.
  double topSpeed() const { return max_wheel_speed_radps * wheel_radius_m; }
  /// The time it takes to drive its own size at top speed, in the study robot's (0.425 s):
  /// exactly 1 for the study's robot, 3.33 for a 4.25 m car at 3 m/s. Durations tuned for the
  /// study's robot (a steering horizon) are this many times longer for another.
  double timeScale() const { return sizeScale() / (topSpeed() / kStudyTopSpeed_mps); }
};

}  // namespace parksim
