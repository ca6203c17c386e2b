#pragma once
// What the figure-making commands (`render`, and `run --frames`) hand to renders/Figures.h.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "parksim/core/Scenario.h"
#include "parksim/planner/PlanScenario.h"
#include "parksim/renders/Figures.h"
#include "parksim/sim/Episode.h"

namespace parksim::app {

/// Adds `--figures none|all|LIST` to a figure-making command, storing the text in `text` (parse
/// it with FigureSelection::parse). An unknown name is a usage error (exit 2) whose one line
/// lists the valid names. `default_help` says what an absent option means.
CLI::Option* addFiguresOption(CLI::App& sub, std::string& text, const std::string& default_help);

/// One line saying which plan a figure shows.
std::string planCaption(const Scenario& scenario, const PlanSetup& setup, const PlanResult& result);

/// A planner's result as a figure input, named after its planner.
PlanFigure planFigure(const Scenario& scenario, const PlanSetup& setup, const PlanResult& result);

/// The study's Fig. 2: the controller from the start toward `target` (default: 0.3 m east and
/// 0.3 m north of the start, heading 0) in both modes.
SteeringExample steeringExample(const Scenario& scenario,
                                const std::optional<Pose2>& target = std::nullopt);

/// Tracking error over time from an episode's rows.
TrackingSeries trackingSeries(const std::vector<ExecutedRow>& rows);

}  // namespace parksim::app
