#pragma once
// The planning problem as a JSON file, for a planner that is a command (CommandPlanner.h): what
// PlanningProblem holds (planner/base/Planner.h) that a program in any language can use, in the
// format `parksim-planning-problem/1` (docs/your-code.md documents every field). The world
// part is also what a controller process is told at its reset (CommandController.h).
//
// Units are in the keys (_m, _rad, _radps, _s); poses are {"x_m", "y_m", "theta_rad"} in the lot
// frame, theta counter-clockwise from +x.

#include <nlohmann/json.hpp>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/planner/base/Planner.h"

namespace parksim {

/// The problem file's format and version: the value of its "format" key.
inline constexpr const char* kProblemFormat = "parksim-planning-problem/1";

/// The world as a planner or a controller sees it: name, source file, lot, robot (its drive,
/// "differential" or "car", and a car's limits: axle distance, track, steering angle and rate,
/// speed, acceleration, curvature), obstacles
/// (name, kind, shape and its geometry, height, whether it blocks the robot), start and goal
/// with its tolerances.
nlohmann::json worldJson(const Scenario& scenario);

/// A pose as {"x_m", "y_m", "theta_rad"}.
nlohmann::json poseJson(const Pose2& pose);

/// The whole problem file: format, world, the timing limits plans are timed at, the motion
/// check's resolution, the budget (iterations, wall time, seed) and `params` (the planner's
/// parameters parksim does not read itself, as text).
nlohmann::json problemJson(const PlanningProblem& problem, const ParamMap& params);

}  // namespace parksim
