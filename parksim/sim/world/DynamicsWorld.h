#pragma once
// The dynamics world of one episode: ground, the scenario's obstacles and the ego robot in
// Bullet (btMultiBodyDynamicsWorld). Static obstacles are fixed boxes; parked robots are boxes
// with mass, so a collision pushes them (they are fixed until the robot comes near: SimModelDef).
// The ego robot is a btMultiBody: a chassis box that is exactly the planner's footprint, two driven
// sphere wheels on velocity motors, and a frictionless sphere slider at the rear. Wheels and slider
// collide with the ground only, the chassis with obstacles only, so the robot's footprint in
// contact is the 80 x 85 mm rectangle.
//
// Bullet stays behind this header (pimpl): nothing that includes sim/ sees a Bullet type.

#include <cstddef>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/sim/world/CarModelDef.h"

namespace parksim {

/// How the constraint solver's iterations are computed (same model, same iteration count).
/// kExact and kFast run parksim's transcription of Bullet 3.24's solver (sim/bullet/README.md),
/// which a build has only against Bullet 3.24 and with PARKSIM_BULLET_FAST_SOLVER on
/// (docs/building.md); any other build runs kBullet for them (effectiveSolverKernel).
enum class SolverKernel {
  /// Bullet's own btMultiBodyConstraintSolver: the reference.
  kBullet,
  /// parksim's transcription of Bullet's iterations (sim/bullet/FastMultiBodySolver.h): the same
  /// float operations in the same order, bit-identical results (tested), ~1.45x faster.
  kExact,
  /// As kExact, and faster: each row's 8-term dot product is summed pairwise instead of left to
  /// right (a quarter of the latency in the solver's critical path); the robot's contact and
  /// motor rows are set up from its mass matrix, constant in its base frame, instead of an
  /// articulated-body pass per row (sim/bullet/MultiBodyInverseMass.h); the wheels' and slider's
  /// ground
  /// contacts are the exact closest point of the ground instead of GJK's
  /// (sim/contacts/SphereBoxContacts.h). Without warm starting, results differ from Bullet's by a
  /// few
  /// micrometres (tested against kBullet).
  kFast,
};

/// How the wheel joints are driven.
enum class WheelDrive {
  /// Bullet velocity motors that reach their target as fast as PhysicsDef::max_wheel_torque_nm
  /// and friction allow: the idealised robot (setWheelTargets).
  kVelocityMotor,
  /// Joint torques set by the caller every step (setWheelTorques, e.g. a DC-motor model), plus
  /// a Coulomb joint friction (TrueRobotDef::joint_friction_nm) solved as a constraint so a
  /// wheel sticks while the torque stays below it.
  kTorque,
};

/// The robot as built, against the nominal RobotDef that the planner and controller use.
/// Defaults build exactly the nominal robot.
struct TrueRobotDef {
  WheelDrive drive = WheelDrive::kVelocityMotor;
  /// True wheel radius = nominal x scale, per wheel (calibration error).
  double left_radius_scale = 1.0;
  double right_radius_scale = 1.0;
  /// True distance between the wheels' contact points = nominal wheel_base_m x scale.
  double track_scale = 1.0;
  /// Moment of inertia of each wheel about its axle including everything geared to it (the
  /// motor's rotor reflected through the gearbox), kg m^2; 0: the wheel sphere's own.
  double wheel_axle_inertia_kgm2 = 0.0;
  /// Coulomb friction torque of each wheel's drive train (gearbox, bearings, rolling
  /// resistance), N m; kTorque only.
  double joint_friction_nm = 0.0;
};

/// Parts of the model that the world file does not describe. Defaults are the model parksim
/// was measured with (docs/simulation.md).
struct SimModelDef {
  /// The passive sliders the robot rests on besides its wheels (RobotSupports.h): the study
  /// robot's one at the rear; lengths are the study robot's, scaled with the robot's size.
  /// Radius of a slider's sphere, m.
  double support_radius_m = 0.008;
  /// Distance from the footprint's end (rear or front) to the slider's contact point, m.
  double support_inset_m = 0.010;
  /// A robot that needs a slider at each end rests on sprung ones: each slider's contact
  /// yields by this much under the robot's whole weight, m, critically damped. A rigid fourth
  /// point would take load from the wheels at random (a stand on four rigid points is
  /// statically indeterminate), and they would slip.
  double support_deflection_m = 0.0002;
  /// Mass of each slider, kg (a link needs mass; it adds to PhysicsDef::chassis_mass_kg).
  double support_mass_kg = 0.002;
  /// Parked robots are fixed boxes until the robot's footprint comes closer than this to one,
  /// m; from the next step on it is a body with mass (Obstacle::mass_kg, by default
  /// PhysicsDef::parked_robot_mass_kg) that
  /// can be pushed. 10 mm is 12 steps ahead at the top speed (0.2 m/s). Resting bodies with
  /// mass cost more than the robot itself (8 of them: 4-5x the step time), and Bullet's own
  /// sleeping does not help: it wakes a body whenever the robot's bounding box, grown by 2 cm,
  /// overlaps it.
  double parked_wake_distance_m = 0.010;
  /// Once woken, a parked robot falls asleep again after 2 s below this speed, m/s (and yaw
  /// rate, rad/s). The ego robot never sleeps.
  double parked_sleep_speed_mps = 1e-3;
  double parked_sleep_yaw_rate_radps = 1e-2;
  /// Worlds with more parked robots than this insert each into Bullet only once the robot
  /// comes within about parked_insert_distance_m (m) of it; Bullet loops over every object it
  /// holds at every step (islands, bounding boxes), so far robots would cost time. Smaller
  /// worlds insert all at the start, in scenario order, as parksim always did (the order of
  /// Bullet's objects decides float rounding in the solver).
  std::size_t parked_lazy_count = 64;
  double parked_insert_distance_m = 1.0;
  /// Contact points of the wheels and the slider farther above the ground than this are not
  /// solved, m. A rolling sphere's contact manifold keeps up to three stale points that rolled
  /// up and away (12 um to 0.6 mm above the ground, zero impulse at the end of every step):
  /// solving them as speculative contacts cost time and changed nothing measurable. The
  /// current contact point sits within 0.1 um of the ground. The chassis keeps Bullet's
  /// default (every point, so contacts with obstacles are speculative as before).
  double wheel_contact_processing_m = 1e-5;
  SolverKernel solver = SolverKernel::kFast;
  /// kExact and kFast: each step's contact and motor rows of the robot start from the impulses
  /// they ended the last step with (sim/bullet/SolverWarmStart.h), so steady driving converges in a
  /// few iterations and stays converged (docs/simulation.md); rigid bodies' contacts (woken
  /// parked robots) start from all of theirs (Bullet's warm-starting factor 1, not 0.85).
  /// false: Bullet's own behaviour (kExact is then bit-identical to kBullet).
  bool warm_start = true;
  /// Where Bullet's own solver stands in for a warm-started kExact or kFast (a build without
  /// the transcription: effectiveSolverKernel), it runs at least this many iterations a step,
  /// since its rows start from zero every step. With PhysicsDef's 15 a resting robot drifted
  /// 0.86 mm in 10 s and an arc's heading settled 0.33 deg off; with 50 (the cap before warm
  /// starting) a chassis driven into a bollard stayed 1.9 mm inside it; from 60 on it is pushed
  /// out as with the warm start (docs/simulation.md, "Bullet's internals fenced").
  int cold_solver_iterations = 100;
  /// The solver stops iterating once no row changed its velocity by more than the square
  /// root of this in the last iteration, (m/s)^2 (Bullet's m_leastSquaresResidualThreshold;
  /// PhysicsDef::solver_iterations stays the maximum). 3e-7 is about 0.5 mm/s: the largest
  /// value with which the step-response and rest tests keep their bounds (1e-6 drifts
  /// 0.1 mm at rest); it saves about 10 % of a step. 0 always runs every iteration.
  double solver_residual_threshold = 3e-7;
  /// The robot as built (calibration errors, drive train); defaults: the nominal robot.
  TrueRobotDef body;
  /// A car's tyres and steering servo (RobotDef::isCar; sim/CarBody.h).
  CarModelDef car;
  /// Where the robot is expected to drive (e.g. the plan's bounding box, lot frame). The ground
  /// slab under it spans this region plus ground_margin_m, clipped to the lot plus 1 m: sized
  /// for float precision (a slab as large as a 200 m lot rounds contact points by ~1e-5 m),
  /// not to the lot. Unset: the whole lot plus 1 m.
  bool has_reach = false;
  LotBounds reach;
  double ground_margin_m = 3.0;
  /// Bullet runs in a local frame whose origin is the start position rounded down to a
  /// multiple of this, m (a power of two, so that lot coordinates minus the origin are exact
  /// and a lot shifted by a multiple of it simulates bit-identically). Bullet's floats then
  /// keep ~1e-6 m wherever the lot lies.
  double local_frame_grid_m = 16.0;
};

/// The kernel a world built with `requested` runs: `requested`, or kBullet in a build without
/// the transcription of Bullet 3.24's solver.
SolverKernel effectiveSolverKernel(SolverKernel requested);

/// Origin of Bullet's local frame in the lot frame for a robot starting at `start`: its
/// position rounded down to the grid (SimModelDef::local_frame_grid_m), heading 0. The
/// dynamics world and the episode that shifts the plan into that frame share it.
Pose2 localFrameOrigin(const Pose2& start, double grid_m);

/// The ego robot's measured state.
struct RobotState {
  /// Reference point (axle middle) projected on the ground, and heading of the chassis.
  Pose2 pose;
  /// The same in Bullet's lot-local frame (SimModelDef::local_frame_grid_m): pose minus the
  /// frame's origin, without the rounding of adding and removing the origin.
  Pose2 local_pose;
  /// Height of the axle middle above the ground, m (the wheel radius when resting).
  double axle_height_m = 0.0;
  /// Angle between the chassis' up axis and the world's, rad.
  double tilt_rad = 0.0;
  /// Forward speed of the reference point along the heading and yaw rate.
  Twist twist;
  /// Wheel joint speeds; positive drives forward.
  WheelSpeeds wheels;
  /// Wheel joint angles, rad (positive forward, from 0 at the start).
  WheelSpeeds wheel_angles;
  /// Slip of each wheel: its rim speed (joint speed x true radius) minus the ground speed of
  /// its contact point along the heading, m/s.
  WheelSpeeds slip_mps;
  /// A car's steering, the bicycle angle of its front wheels' joint angles (Ackermann.h), rad;
  /// 0 for a differential drive.
  double steer_rad = 0.0;
  /// The rate-limited bicycle angle its steering servos follow, rad (DynamicsWorld::
  /// setSteerTarget); 0 for a differential drive.
  double steer_setpoint_rad = 0.0;
  /// False if Bullet put the robot to sleep (it must never happen: sleeping is disabled).
  bool awake = true;
};

class DynamicsWorld {
 public:
  /// Builds the world with the ego robot at `start` (not necessarily scenario.start). Copies
  /// what it needs; keeps no reference to `scenario`. Throws Error on non-positive sizes,
  /// masses or time step.
  DynamicsWorld(const Scenario& scenario, const Pose2& start, const SimModelDef& model = {});
  ~DynamicsWorld();

  DynamicsWorld(const DynamicsWorld&) = delete;
  DynamicsWorld& operator=(const DynamicsWorld&) = delete;

  /// Velocity targets of the two wheel motors, held until changed. The motors reach them as
  /// fast as the torque limit (PhysicsDef::max_wheel_torque_nm) and ground friction allow.
  void setWheelTargets(const WheelSpeeds& targets);
  const WheelSpeeds& wheelTargets() const;

  /// A car (RobotDef::isCar): the bicycle angle its steering turns to, rad, held until
  /// changed. The servos' set-point moves toward it at most robot.max_steer_rate_radps and
  /// stays within +-robot.max_steer_rad (sim/CarBody.h). A differential drive ignores it.
  void setSteerTarget(double steer_rad);
  double steerTarget() const;

  /// WheelDrive::kTorque: the torque of each wheel's motor for the next step, N m (positive
  /// drives forward). Ignored with kVelocityMotor.
  void setWheelTorques(const WheelSpeeds& torques_nm);

  /// The true wheel radii and track (TrueRobotDef applied to the nominal robot), m.
  double leftWheelRadius() const;
  double rightWheelRadius() const;
  double track() const;

  /// Advances by one fixed step (PhysicsDef::time_step_s).
  void step();

  double timeStep() const;
  /// Simulated time since construction: steps() * timeStep(), s.
  double time() const;
  long steps() const;

  /// The robot's state after the last step (computed once per step).
  const RobotState& robot() const;

  /// Planar pose (box centre, yaw) of every obstacle, in scenario order.
  std::vector<Pose2> obstaclePoses() const;
  /// Planar position of obstacle `index`'s box centre (scenario order), m.
  Eigen::Vector2d obstaclePosition(std::size_t index) const;
  /// Height of every obstacle's box centre above the ground, m, in scenario order.
  std::vector<double> obstacleHeights() const;

  /// Indices (scenario order, ascending) of the obstacles the chassis penetrates after the
  /// last step: contact points at negative distance, so touching within Bullet's contact
  /// threshold without overlap does not count.
  const std::vector<int>& chassisContacts() const;

  /// Indices (scenario order) of the parked robots that have become bodies with mass, in the
  /// order they did; every other obstacle has not moved since the start.
  const std::vector<int>& movableObstacles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
