#pragma once
// The study's figures, done right, as Scenes (pure) and as PNG files:
//   lot_map.png        Fig. 3  the lot: obstacles, start (red) and goal (green) arrows
//   steering.png       Fig. 2  move-to-pose steering from a start to a target, in both modes
//   cspace_slice.png   Fig. 5  exact C-space obstacles (Minkowski slices) at one heading
//   cspace_stack.png   Fig. 6  the same slices stacked over the heading axis, in 3D
//   plan_<name>.png    Figs. 7-9  planned trajectory with footprint outlines and the tree
//   tracking_error.png         position and heading error versus time of an executed episode
//   lot_3d.png                 the lot in perspective, with the plan when there is one
//
// The figures with axes (lot_map, cspace_slice, plan_*: the lot; steering: its data extent)
// clip their content to that plot area (SceneClip.h) before the axes, ticks and title go into
// the margin around it, so obstacles beyond the lot never cover them. cspace_stack is clipped
// to the lot too (C-space is the lot times the headings). lot_3d is a picture of the whole
// world, with no axes: it is not clipped, and its camera frames everything.

#include <optional>
#include <string>
#include <vector>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/renders/gl/OffscreenContext.h"
#include "parksim/renders/plots/FigureSelection.h"
#include "parksim/renders/plots/TrackingPlot.h"
#include "parksim/renders/scene/Camera.h"
#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

struct FigureDef {
  int width_px = 1200;   ///< pixels
  int height_px = 800;   ///< pixels
  int msaa_samples = 4;  ///< anti-aliasing samples per pixel
  /// Colours and widths for a 480-pixel-high image; scaled to height_px.
  SceneStyle style;
  double cspace_heading_rad =
      degToRad(-60.0);                ///< heading of the C-space slice figure (study: -60)
  int cspace_slices = 36;             ///< slices in the stacked C-space figure
  double footprint_spacing_m = 0.07;  ///< plan figures: path length between footprint outlines, m
  double footprint_turn_rad = degToRad(30.0);  ///< ... or heading change, rad
  /// The OpenGL backend (default auto: PARKSIM_GL_BACKEND, else EGL, then OSMesa).
  ContextDef context;
  /// The figures writeFigures writes (FigureSelection.h); the others are not built.
  FigureSelection figures = FigureSelection::all();
};

/// Steering from `start` toward `target` in both of the study's modes.
struct SteeringExample {
  Pose2 start;
  Pose2 target;
  Trajectory fixed_horizon;  ///< SteerMode::kFixedHorizon (solid line)
  Trajectory to_goal;        ///< SteerMode::kToGoal (dashed line)
};

/// A planner's result, as plain data.
struct PlanFigure {
  std::string name;     ///< file name part: plan_<name>.png
  std::string caption;  ///< title line
  Trajectory trajectory;
  std::vector<Pose2> waypoints;        ///< tree nodes on the solution
  std::vector<Trajectory> tree_edges;  ///< every edge of the tree
};

Scene buildLotMapFigure(const Scenario& scenario, const SceneStyle& style);
Scene buildSteeringFigure(const Scenario& scenario, const SteeringExample& example,
                          const SceneStyle& style);
Scene buildCSpaceSliceFigure(const Scenario& scenario, double theta_rad, const SceneStyle& style);
/// Heading maps to height: -180 degrees at the ground, +180 at extent_top_m.
Scene buildCSpaceStackFigure(const Scenario& scenario, int slices, const SceneStyle& style);
Scene buildPlanFigure(const Scenario& scenario, const PlanFigure& plan, const FigureDef& def,
                      const SceneStyle& style);
/// The lot seen in perspective, with the plan's path and the robot at the start.
Scene buildLot3dFigure(const Scenario& scenario, const PlanFigure* plan, const SceneStyle& style);

/// The camera each figure is meant to be seen through: perspective for cspace_stack and lot_3d,
/// top-down for the others.
CameraDef figureCamera(const std::string& figure_name);

struct FigureInputs {
  std::optional<SteeringExample> steering;
  std::vector<PlanFigure> plans;
  std::optional<TrackingSeries> tracking;
};

/// Renders every figure of `def.figures` the inputs allow (lot_map, cspace_slice, cspace_stack
/// and lot_3d always; steering, plan_* and tracking_error when given) into `dir` (created if
/// missing) and returns the paths written, in the order above. Writes nothing, creates no
/// directory and needs no GL context when none is chosen. Throws Error when a file cannot be
/// written or no GL context can be made.
std::vector<std::string> writeFigures(const Scenario& scenario, const FigureInputs& inputs,
                                      const FigureDef& def, const std::string& dir);

/// Writes the tracking plot alone (for the run command), creating the file's directory.
/// Throws Error.
void writeTrackingPlot(const TrackingSeries& series, const std::string& title, const FigureDef& def,
                       const std::string& path);

}  // namespace parksim
