#pragma once
// An episode's parts as the renderer's plain inputs: a plan as a figure, the study's steering
// example, the tracking-error series, and a simulation sample as a film frame. The bridge
// between planning and simulation on one side and renders/ (which depends on neither) on the
// other.

#include <optional>
#include <string>
#include <vector>

#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/plots/Figures.h"
#include "parksim/renders/plots/TrackingPlot.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim {

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

/// Tracking error over time from a record file: an executed.npz (columns t, pos_err,
/// heading_err; results/ExecutedFile.h) or any CSV file readTrackingCsv reads. Throws Error
/// naming the file on a missing column, no rows, or time that does not increase.
TrackingSeries readTrackingRecord(const std::string& path);

/// What FrameRecorder::addFrame needs from one observer call of runEpisode.
FrameInput frameInput(const EpisodeSample& sample);

}  // namespace parksim
