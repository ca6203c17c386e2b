#pragma once
// Colours and line widths of everything parksim draws, with defaults chosen to read well on
// screen and in print. Widths are pixels at a 480-pixel-high image; scaled() adapts them to
// another image size so a 1080p frame does not get hairlines.

#include "parksim/core/model/Scenario.h"
#include "parksim/renders/image/Color.h"

namespace parksim {

struct SceneStyle {
  Rgba8 background = rgb(205, 209, 214);    ///< outside the lot
  Rgba8 lot = rgb(246, 246, 242);           ///< the lot's surface
  Rgba8 lot_border = rgb(120, 124, 130);    ///< outline of the lot bounds
  Rgba8 grid = rgb(226, 227, 222);          ///< ground grid lines
  Rgba8 wall = rgb(60, 62, 68);             ///< ObstacleKind::kWall
  Rgba8 curb = rgb(150, 140, 120);          ///< ObstacleKind::kCurb
  Rgba8 island = rgb(96, 140, 88);          ///< ObstacleKind::kIsland
  Rgba8 box = rgb(140, 110, 80);            ///< ObstacleKind::kBox
  Rgba8 bollard = rgb(214, 170, 40);        ///< ObstacleKind::kBollard
  Rgba8 pillar = rgb(140, 140, 150);        ///< ObstacleKind::kPillar
  Rgba8 parked_robot = rgb(70, 110, 170);   ///< ObstacleKind::kParkedRobot
  Rgba8 contact = rgb(230, 50, 40);         ///< an obstacle the robot is touching
  Rgba8 robot = rgb(242, 140, 30);          ///< the ego robot's body
  Rgba8 robot_marker = rgb(255, 255, 255);  ///< heading triangle on top of the body
  Rgba8 wheel = rgb(35, 35, 38);
  Rgba8 reference = rgb(150, 30, 160);  ///< outline of the reference (planned) pose
  Rgba8 start = rgb(220, 40, 40);       ///< start arrow (red, as in the study)
  Rgba8 goal = rgb(30, 160, 60);        ///< goal arrow and goal outline (green)
  Rgba8 tree = rgb(170, 185, 205);      ///< tree edges
  Rgba8 waypoint = rgb(90, 100, 120);   ///< tree nodes on the solution
  Rgba8 planned = rgb(30, 90, 200);     ///< planned path
  Rgba8 executed = rgb(235, 90, 20);    ///< executed path
  Rgba8 footprint = rgb(40, 40, 40);    ///< footprint outlines along a path
  Rgba8 cspace = rgb(200, 60, 60);      ///< C-space obstacle slices
  /// A map's occupied and unknown cells as its file says them, drawn faintly under the lot's
  /// obstacles (a world's `map:` section), so that an import can be seen to be right.
  Rgba8 map_occupied{40, 40, 48, 70};
  Rgba8 map_unknown{70, 110, 200, 45};
  Rgba8 text = rgb(20, 20, 20);
  Rgba8 text_background{255, 255, 255, 200};
  Rgba8 axis = rgb(60, 60, 60);  ///< plot and figure axes, ticks

  float grid_px = 1.0f;
  float border_px = 1.5f;
  float tree_px = 1.0f;
  float path_px = 2.5f;
  float outline_px = 1.2f;
  float arrow_px = 3.0f;
  float text_px = 15.0f;

  /// Lengths for the study's 85 mm robot; forRobot() scales them to another robot's size.
  double grid_spacing_m = 0.1;  ///< ground grid period, m; 0 draws no grid
  double arrow_length_m = 0.1;  ///< start and goal arrows, m
  double margin_m = 0.04;       ///< ground shown around the lot bounds, m
  int circle_segments = 64;     ///< sides of the polygon that draws a round obstacle

  Rgba8 colorFor(ObstacleKind kind) const;
  /// Every width and text size multiplied by `factor` (> 0).
  SceneStyle scaled(double factor) const;
  /// The lengths in metres (grid, arrows, ground margin) multiplied by the robot's size in
  /// study robots (RobotDef::sizeScale): a car's lot gets a 5 m grid and 5 m arrows. The
  /// study's robot keeps this style exactly.
  SceneStyle forRobot(const RobotDef& ego) const;
};

/// The factor that makes a style drawn for 480-pixel-high images fit `height_px`.
inline double styleScaleFor(int height_px) { return height_px / 480.0; }

}  // namespace parksim
