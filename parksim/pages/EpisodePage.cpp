#include "parksim/pages/EpisodePage.h"

#include <vector>

#include "parksim/pages/ColumnCodec.h"
#include "parksim/pages/LotData.h"
#include "parksim/pages/PageDocument.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/MetricsFile.h"

namespace parksim {
namespace {

// metrics.json keys measured in wall-clock time: left out so that a page depends on the
// episode alone.
bool isWallClockMetric(const std::string& key) {
  return key == "wall_time_s" || key == "real_time_factor";
}

// plan.json's keys a reader of an episode wants (none measures wall-clock time).
constexpr const char* kPlanKeys[] = {"planner",
                                     "steering",
                                     "timing",
                                     "smooth",
                                     "seed",
                                     "status",
                                     "message",
                                     "solved",
                                     "iterations",
                                     "tree_size",
                                     "objective",
                                     "path_length_m",
                                     "duration_s",
                                     "cusps",
                                     "cost_s",
                                     "cost_m",
                                     "waypoints",
                                     "final_pos_err_m",
                                     "final_heading_err_deg"};

nlohmann::json planData(const Scenario& scenario, const Trajectory& plan) {
  std::vector<double> t, x, y, theta;
  for (const TrajectoryPoint& p : plan.points) {
    t.push_back(p.t_s);
    x.push_back(p.pose.x);
    y.push_back(p.pose.y);
    theta.push_back(p.pose.theta);
  }
  // The path along its exact arcs, as the renderer draws it.
  std::vector<double> px, py;
  for (const Pose2& p : samplePath(plan, scenario.robot)) {
    px.push_back(p.x);
    py.push_back(p.y);
  }
  return {{"rows", plan.points.size()},
          {"t", float64Column(t)},
          {"x", float64Column(x)},
          {"y", float64Column(y)},
          {"theta", float64Column(theta)},
          {"path", {{"x", float64Column(px)}, {"y", float64Column(py)}}}};
}

nlohmann::json recordData(const EpisodePage& page, bool car) {
  // Every row up to the limit; beyond it every stride-th row and the last, so a page of the
  // longest episode the step limit allows stays one a browser opens (docs/limits.md).
  const std::size_t rows = page.rows.size();
  const std::size_t stride = (rows + kMaxEpisodePageRows - 1) / kMaxEpisodePageRows;
  std::vector<ExecutedRow> kept;
  if (stride > 1) {
    for (std::size_t i = 0; i < rows; i += stride) kept.push_back(page.rows[i]);
    if ((rows - 1) % stride != 0) kept.push_back(page.rows.back());
  }
  const std::span<const ExecutedRow> shown =
      stride > 1 ? std::span<const ExecutedRow>(kept) : page.rows;
  nlohmann::json columns = nlohmann::json::object();
  nlohmann::json names = nlohmann::json::array();
  for (const DataColumn& c :
       executedColumns({shown.begin(), shown.end()}, page.realism_columns, car)) {
    names.push_back(c.name);
    columns[c.name] = float64Column(c.values);
  }
  return {{"rows", shown.size()},
          {"stride", stride > 1 ? stride : 1},
          {"names", std::move(names)},
          {"columns", std::move(columns)}};
}

nlohmann::json toleranceData(const TrackingTolerance& t) {
  return {{"max_pos_err_m", t.max_pos_err_m},
          {"goal_pos_err_m", t.goal_pos_err_m},
          {"goal_heading_err_deg", t.goal_heading_err_deg},
          {"max_contacts", t.max_contacts},
          {"max_parked_displacement_m", t.max_parked_displacement_m}};
}

}  // namespace

nlohmann::json episodePageData(const Scenario& scenario, const EpisodePage& page) {
  nlohmann::json data = lotData(scenario);
  data["page"] = "episode";
  data["scenario"] = scenario.name;
  data["world_file"] = scenario.source_path;
  data["verdict"] = {
      {"status", page.status}, {"met", page.status == "met"}, {"reason", page.reason}};
  data["realisations"] = {{"count", page.realisations}, {"met", page.realisations_met}};
  if (page.plan != nullptr && !page.plan->empty()) data["plan"] = planData(scenario, *page.plan);
  // A car's record carries its steering, and the replay turns its front wheels by it.
  if (!page.rows.empty()) data["record"] = recordData(page, scenario.robot.isCar());
  if (page.tolerance != nullptr) data["tolerance"] = toleranceData(*page.tolerance);
  if (page.metrics != nullptr) {
    nlohmann::json metrics = nlohmann::json::object();
    const nlohmann::json all = metricsToJson(*page.metrics);
    for (const auto& [key, value] : all.items()) {
      if (!isWallClockMetric(key)) metrics[key] = value;
    }
    data["metrics"] = std::move(metrics);
    nlohmann::json contacts = nlohmann::json::array();
    for (const ContactEvent& c : page.metrics->contact_events) {
      contacts.push_back({{"t_s", c.t_s}, {"obstacle", c.obstacle_index}, {"body", c.body}});
    }
    data["contacts"] = std::move(contacts);
  }
  if (page.plan_summary != nullptr && page.plan_summary->is_object()) {
    nlohmann::json plan = nlohmann::json::object();
    for (const char* key : kPlanKeys) {
      if (const auto it = page.plan_summary->find(key); it != page.plan_summary->end()) {
        plan[key] = *it;
      }
    }
    data["plan_summary"] = std::move(plan);
  }
  return data;
}

void writeEpisodePage(const std::string& path, const Scenario& scenario, const EpisodePage& page) {
  PageDocument doc;
  doc.title = "parksim episode: " + scenario.name + " (" + page.status + ")";
  doc.libraries = {PageLibraryId::kUPlot};
  doc.scripts = {"replay.js", "episode.js"};
  doc.data = episodePageData(scenario, page);
  writePage(path, std::move(doc));
}

}  // namespace parksim
