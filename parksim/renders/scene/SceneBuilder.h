#pragma once
// Builds the Scene of a parking episode from the immutable Scenario and a plain view state: the
// lot, obstacles where they are now, the start and goal, the plan, the path driven so far and
// the robot. Pure: no OpenGL, no files.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

/// Text shown in the corner of a frame.
struct Overlay {
  std::string title;               ///< first line, e.g. the scenario name; may be empty
  double time_s = 0.0;             ///< simulated time, s
  double position_error_m = 0.0;   ///< current tracking error, m
  double heading_error_rad = 0.0;  ///< current tracking error, rad
};

/// Everything about an instant that is not in the Scenario. Spans are views: whatever they point
/// at must outlive the buildScene call (not the Scene, which copies what it needs).
struct ViewState {
  std::optional<Pose2> robot;  ///< executed pose of the reference point; unset: no robot
  /// A car's steering angle (bicycle model), rad: its front wheels are drawn turned by their
  /// Ackermann angles of it (core/model/Ackermann.h).
  double robot_steer_rad = 0.0;
  std::optional<Pose2> reference;  ///< pose the robot should be at now: drawn as an outline
  /// Box centre and yaw of every obstacle in scenario order (pushed robots move); empty: as in
  /// the scenario.
  std::span<const Pose2> obstacle_poses;
  /// Indices of obstacles touching the robot now; drawn in the contact colour.
  std::span<const int> contacts;
  std::span<const Pose2> planned_path;   ///< densely sampled planned path (see samplePath)
  std::span<const Pose2> executed_path;  ///< path driven so far
  std::span<const Trajectory> tree_edges;
  std::optional<Overlay> overlay;  ///< text in the top-left corner; unset: none
};

/// The lot, obstacles, start and goal; what every picture of a scenario starts from.
/// `obstacle_poses` and `contacts` as in ViewState.
Scene buildLotScene(const Scenario& scenario, const SceneStyle& style,
                    std::span<const Pose2> obstacle_poses = {}, std::span<const int> contacts = {});

/// The lot scene plus the view state's paths, tree, robot and overlay.
Scene buildScene(const Scenario& scenario, const ViewState& view, const SceneStyle& style);

/// A view's scene in two layers, for films. `back` holds what changes only when obstacles move
/// or touch the robot: the lot, obstacles, goal outline, tree and planned path. `front` holds
/// the rest, over it: the driven path, robot, reference outline, start and goal arrows and the
/// overlay, with back's background and extent. appendScene(back, front) is buildScene's scene.
struct SceneLayers {
  Scene back;
  Scene front;
};

SceneLayers buildSceneLayers(const Scenario& scenario, const ViewState& view,
                             const SceneStyle& style);

/// Poses along a trajectory, following its exact arcs (integrateExact), no farther apart than
/// `max_step_m` in position or `max_turn_rad` in heading. Includes the first and last pose.
std::vector<Pose2> samplePath(const Trajectory& trajectory, const RobotDef& robot,
                              double max_step_m = 0.005, double max_turn_rad = 0.1);

/// Adds the robot at `pose`: body, wheels and a heading marker on top. A car (RobotDef::isCar)
/// gets its front wheels too, axle_distance ahead, turned by steering angle `steer_rad`.
void addRobot(Scene& scene, const RobotDef& robot, const Pose2& pose, const SceneStyle& style,
              double steer_rad = 0.0);

/// Adds `poses` as a polyline at height z_m.
void addPath(Scene& scene, std::span<const Pose2> poses, double z_m, Rgba8 color, float width_px);

/// Heights of the flat layers, m: later layers sit slightly higher so the depth test and the
/// painter's order agree in every view.
struct Layers {
  static constexpr double kGround = 0.0;
  static constexpr double kMap = 0.0001;  ///< a map's cells under the lot (MapLayer)
  static constexpr double kGrid = 0.0002;
  static constexpr double kCSpace = 0.0004;
  static constexpr double kTree = 0.0006;
  static constexpr double kPlanned = 0.0008;
  static constexpr double kExecuted = 0.0010;
  static constexpr double kOutline = 0.0012;
  static constexpr double kArrow = 0.0015;
};

}  // namespace parksim
