#pragma once
// A scenario as an episode page draws it (web/replay.js): the lot's bounds, every obstacle's
// outline and colour, the robot's footprint, the start and the goal with its tolerance, and
// the colours of everything else: the colours are the renderer's (renders/scene/SceneStyle.h), so a
// page and a film of the same episode look alike.

#include <nlohmann/json.hpp>

#include "parksim/core/model/Scenario.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

/// {"lot": {x_min, y_min, x_max, y_max}, "obstacles": [{name, kind, color, points: [x0, y0,
/// x1, ...]}], "robot": {length_m, width_m, front_overhang_m, wheel_base_m, wheel_radius_m},
/// "start": [x, y, theta], "goal": {pose: [x, y, theta], position_tolerance_m,
/// heading_tolerance_rad, either_heading}, "style": {name: "#rrggbb"}}; metres and radians.
nlohmann::json lotData(const Scenario& scenario, const SceneStyle& style = {});

/// "#rrggbb" (alpha dropped).
std::string cssColor(Rgba8 color);

}  // namespace parksim
