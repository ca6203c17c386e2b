#include "parksim/pipeline/EpisodeFigures.h"

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/planner/steering/MoveToPoseSteering.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/TrajectoryFile.h"

namespace parksim {

std::string planCaption(const Scenario& scenario, const PlanSetup& setup,
                        const PlanResult& result) {
  const std::string head =
      scenario.name + ", " + setup.planner + " (seed " + std::to_string(setup.search.seed) + "): ";
  if (result.solved()) {
    const int cusps = result.trajectory.cusps(scenario.robot);
    return head + std::to_string(result.stats.tree_size) + " tree nodes, path " +
           formatFixed(result.trajectory.pathLength(scenario.robot), 2) + " m, " +
           std::to_string(cusps) + (cusps == 1 ? " cusp" : " cusps");
  }
  return head + toString(result.status) + " after " + std::to_string(result.stats.iterations) +
         " iterations";
}

PlanFigure planFigure(const Scenario& scenario, const PlanSetup& setup, const PlanResult& result) {
  return {setup.planner, planCaption(scenario, setup, result), result.trajectory, result.waypoints,
          result.tree_edges};
}

SteeringExample steeringExample(const Scenario& scenario, const std::optional<Pose2>& target) {
  SteeringExample example;
  example.start = scenario.start;
  example.target = target.value_or(Pose2{scenario.start.x + 0.3, scenario.start.y + 0.3, 0.0});
  const MoveToPoseSteering steer(scenario.robot);
  example.fixed_horizon =
      steer.steer(example.start, {}, example.target, SteerMode::kFixedHorizon).trajectory;
  example.to_goal = steer.steer(example.start, {}, example.target, SteerMode::kToGoal).trajectory;
  return example;
}

TrackingSeries trackingSeries(const std::vector<ExecutedRow>& rows) {
  TrackingSeries series;
  for (const ExecutedRow& row : rows) {
    series.t_s.push_back(row.t_s);
    series.position_error_m.push_back(row.pos_err_m);
    series.heading_error_rad.push_back(row.heading_err_rad);
  }
  return series;
}

TrackingSeries readTrackingRecord(const std::string& path) {
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".npz") != 0) {
    // The plan reader's limits (docs/limits.md), on the columns the plot reads.
    std::vector<std::string_view> heading(std::begin(kTrackingHeadingRadNames),
                                          std::end(kTrackingHeadingRadNames));
    heading.insert(heading.end(), std::begin(kTrackingHeadingDegNames),
                   std::end(kTrackingHeadingDegNames));
    checkTimeSeriesCsv(path,
                       {{std::begin(kTrackingTimeNames), std::end(kTrackingTimeNames)},
                        {std::begin(kTrackingPositionNames), std::end(kTrackingPositionNames)},
                        heading});
    return readTrackingCsv(path);
  }
  const std::vector<DataColumn> columns = readNpzFile(path);
  const DataColumn* t = findColumn(columns, "t");
  const DataColumn* p = findColumn(columns, "pos_err");
  const DataColumn* h = findColumn(columns, "heading_err");
  if (t == nullptr || p == nullptr || h == nullptr) {
    throw Error(path + ": needs arrays t, pos_err and heading_err (an executed.npz)");
  }
  if (t->values.empty()) throw Error(path + ": no rows");
  if (p->values.size() != t->values.size() || h->values.size() != t->values.size()) {
    throw Error(path + ": arrays t, pos_err and heading_err differ in length");
  }
  for (std::size_t i = 1; i < t->values.size(); ++i) {
    if (!(t->values[i] > t->values[i - 1])) {
      throw Error(path + ": row " + std::to_string(i) + ": time does not increase");
    }
  }
  return {t->values, p->values, h->values};
}

FrameInput frameInput(const EpisodeSample& sample) {
  FrameInput in;
  in.t_s = sample.tracking.t_s;
  in.pose = sample.tracking.pose;
  in.steer_rad = sample.tracking.steer_rad;
  in.reference = sample.tracking.reference;
  in.position_error_m = sample.tracking.pos_err_m;
  in.heading_error_rad = sample.tracking.heading_err_rad;
  in.obstacle_poses = sample.obstacles;
  in.contacts = sample.contacts;
  return in;
}

}  // namespace parksim
