#include "parksim/sweep/Report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "parksim/core/AtomicFile.h"
#include "parksim/renders/BoxPlot.h"
#include "parksim/renders/PngEncoder.h"
#include "parksim/renders/Renderer.h"
#include "parksim/renders/SuccessMatrix.h"
#include "parksim/sweep/EpisodeParams.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

std::string str(const Json& row, const char* key, const char* fallback) {
  const auto it = row.find(key);
  return it != row.end() && it->is_string() ? it->get<std::string>() : fallback;
}

bool flag(const Json& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_boolean() && it->get<bool>();
}

bool number(const Json& row, const char* key, double& out) {
  const auto it = row.find(key);
  if (it == row.end() || !it->is_number()) return false;
  out = it->get<double>();
  return true;
}

std::string medianP95(const std::vector<double>& v, const char* format) {
  if (v.empty()) return "-";
  std::vector<double> s = v;
  std::sort(s.begin(), s.end());
  char buf[64];
  std::snprintf(buf, sizeof buf, format, quantileSorted(s, 0.5), quantileSorted(s, 0.95));
  return buf;
}

std::string median(const std::vector<double>& v, const char* format) {
  if (v.empty()) return "-";
  std::vector<double> s = v;
  std::sort(s.begin(), s.end());
  char buf[64];
  std::snprintf(buf, sizeof buf, format, quantileSorted(s, 0.5));
  return buf;
}

std::string percent(int k, int n) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%d/%d (%.0f%%)", k, n, n > 0 ? 100.0 * k / n : 0.0);
  return buf;
}

std::string csvNumber(const std::vector<double>& v, double q) {
  if (v.empty()) return "";
  std::vector<double> s = v;
  std::sort(s.begin(), s.end());
  return nlohmann::json(quantileSorted(s, q)).dump();
}

std::string groupName(const ReportGroup& g, bool with_realism) {
  std::string s = g.world + "\n" + g.planner;
  if (with_realism) s += " " + g.realism;
  return s;
}

void renderTo(const Scene& scene, int w, int h, const std::string& path) {
  RenderDef r;
  r.width_px = w;
  r.height_px = h;
  Renderer renderer(r);
  RgbImage image;
  CameraDef camera;
  camera.fill = 1.0;
  renderer.render(scene, camera, image);
  writePng(path, image, PngCompression::kSmall);
}

}  // namespace

std::string plannerLabel(const Json& row) {
  // Appended piece by piece: `"x" + std::string` trips GCC 12's false -Wrestrict (bug 105329).
  std::string s = str(row, "planner", "?");
  if (flag(row, "smooth")) s += "+smooth";
  // Labels name what differs from the library's defaults (EpisodeParams{}).
  const EpisodeParams defaults;
  const std::string steering = str(row, "steering", defaults.steering.c_str());
  if (steering != defaults.steering) {
    s += '/';
    s += steering;
  }
  const std::string tracking = str(row, "tracking", defaults.tracking.c_str());
  if (tracking != defaults.tracking) {
    s += ' ';
    s += tracking;
    s += "-loop";
  }
  double iterations = defaults.max_iterations;
  if (number(row, "max_iterations", iterations) && iterations != defaults.max_iterations) {
    s += " it=";
    s += std::to_string(static_cast<long long>(iterations));
  }
  const std::string timing = str(row, "timing", defaults.timing.c_str());
  if (timing != defaults.timing) {
    s += " timing=";
    s += timing;
  }
  return s;
}

RowGroupKey rowGroupKey(const Json& row) {
  return {str(row, "world", "?"), plannerLabel(row), str(row, "realism", "world")};
}

std::string rowGroupName(const RowGroupKey& key) {
  return std::get<0>(key) + " / " + std::get<1>(key) + " / " + std::get<2>(key);
}

std::string rowGroupNameOf(const Json& row) { return rowGroupName(rowGroupKey(row)); }

std::vector<ReportGroup> groupResults(const std::vector<Json>& rows) {
  std::map<RowGroupKey, ReportGroup> groups;
  for (const Json& row : rows) {
    const RowGroupKey key = rowGroupKey(row);
    ReportGroup& g = groups[key];
    std::tie(g.world, g.planner, g.realism) = key;
    ++g.episodes;
    if (flag(row, "plan_solved")) ++g.solved;
    if (flag(row, "met_tolerance")) ++g.met;
    if (flag(row, "goal_reached")) ++g.goal_reached;
    double v = 0.0;
    if (number(row, "max_pos_err_m", v)) g.max_err_mm.push_back(1e3 * v);
    if (number(row, "plan_time_s", v)) g.plan_time_ms.push_back(1e3 * v);
    if (number(row, "plan_path_length_m", v)) g.path_length_m.push_back(v);
    if (number(row, "sim_time_s", v)) g.duration_s.push_back(v);
  }
  std::vector<ReportGroup> out;
  for (auto& [key, g] : groups) out.push_back(std::move(g));
  return out;
}

std::string summaryMarkdown(const std::vector<ReportGroup>& groups) {
  std::string s =
      "| world | planner | realism | episodes | plan solved | met tolerance | goal reached | "
      "max tracking error, median / p95 (mm) | plan time, median / p95 (ms) | path length, "
      "median (m) | duration, median (s) "
      "|\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ReportGroup& g : groups) {
    s += "| " + g.world + " | " + g.planner + " | " + g.realism + " | " +
         std::to_string(g.episodes) + " | " + percent(g.solved, g.episodes) + " | " +
         percent(g.met, g.episodes) + " | " + percent(g.goal_reached, g.episodes) + " | " +
         medianP95(g.max_err_mm, "%.3f / %.3f") + " | " + medianP95(g.plan_time_ms, "%.2f / %.2f") +
         " | " + median(g.path_length_m, "%.3f") + " | " + median(g.duration_s, "%.1f") + " |\n";
  }
  return s;
}

std::string summaryCsv(const std::vector<ReportGroup>& groups) {
  std::string s =
      "world,planner,realism,episodes,plan_solved,met_tolerance,goal_reached,"
      "max_err_mm_median,max_err_mm_p95,plan_time_ms_median,plan_time_ms_p95,"
      "path_length_m_median,duration_s_median\n";
  for (const ReportGroup& g : groups) {
    s += g.world + "," + g.planner + "," + g.realism + "," + std::to_string(g.episodes) + "," +
         std::to_string(g.solved) + "," + std::to_string(g.met) + "," +
         std::to_string(g.goal_reached) + "," + csvNumber(g.max_err_mm, 0.5) + "," +
         csvNumber(g.max_err_mm, 0.95) + "," + csvNumber(g.plan_time_ms, 0.5) + "," +
         csvNumber(g.plan_time_ms, 0.95) + "," + csvNumber(g.path_length_m, 0.5) + "," +
         csvNumber(g.duration_s, 0.5) + "\n";
  }
  return s;
}

std::vector<std::string> writeReport(const std::vector<Json>& rows, const std::string& title,
                                     const std::string& out_dir) {
  ensureDirectory(out_dir);
  const std::vector<ReportGroup> groups = groupResults(rows);
  std::vector<std::string> written;
  writeFileAtomically(out_dir + "/summary.md", "# " + title + "\n\n" + std::to_string(rows.size()) +
                                                   " episodes.\n\n" + summaryMarkdown(groups));
  written.push_back(out_dir + "/summary.md");
  writeFileAtomically(out_dir + "/summary.csv", summaryCsv(groups));
  written.push_back(out_dir + "/summary.csv");

  bool several_presets = false;
  for (const ReportGroup& g : groups) several_presets |= g.realism != groups.front().realism;

  // Success matrix: planner configurations down, worlds (x presets) across.
  std::vector<std::string> row_labels;
  std::vector<std::string> col_labels;
  for (const ReportGroup& g : groups) {
    const std::string col = several_presets ? g.world + " / " + g.realism : g.world;
    if (std::find(row_labels.begin(), row_labels.end(), g.planner) == row_labels.end()) {
      row_labels.push_back(g.planner);
    }
    if (std::find(col_labels.begin(), col_labels.end(), col) == col_labels.end()) {
      col_labels.push_back(col);
    }
  }
  std::sort(row_labels.begin(), row_labels.end());
  std::vector<std::vector<SuccessCell>> cells(row_labels.size(),
                                              std::vector<SuccessCell>(col_labels.size()));
  for (const ReportGroup& g : groups) {
    const std::string col = several_presets ? g.world + " / " + g.realism : g.world;
    const auto r = std::find(row_labels.begin(), row_labels.end(), g.planner) - row_labels.begin();
    const auto c = std::find(col_labels.begin(), col_labels.end(), col) - col_labels.begin();
    cells[r][c] = {g.met, g.episodes};
  }
  const int w = 1200;
  const int h = 700;
  const SceneStyle style = SceneStyle{}.scaled(styleScaleFor(h) * 0.8);
  const int matrix_h = std::clamp(160 + 70 * static_cast<int>(row_labels.size()), 300, 1200);
  renderTo(buildSuccessMatrix(row_labels, col_labels, cells, "Met tolerance: " + title, w, matrix_h,
                              SceneStyle{}.scaled(styleScaleFor(700) * 0.8)),
           w, matrix_h, out_dir + "/success_matrix.png");
  written.push_back(out_dir + "/success_matrix.png");

  struct Figure {
    const char* file;
    const char* title;
    const char* y_label;
    std::vector<double> ReportGroup::*values;
  };
  const Figure figures[] = {
      {"tracking_error.png", "Largest tracking error per episode", "max tracking error (mm)",
       &ReportGroup::max_err_mm},
      {"plan_time.png", "Planning time per episode", "plan time (ms)", &ReportGroup::plan_time_ms},
      {"path_length.png", "Planned path length", "path length (m)", &ReportGroup::path_length_m},
      {"duration.png", "Episode duration (simulated)", "duration (s)", &ReportGroup::duration_s},
  };
  for (const Figure& f : figures) {
    std::vector<BoxSeries> series;
    for (const ReportGroup& g : groups)
      series.push_back({groupName(g, several_presets), g.*f.values});
    renderTo(buildBoxPlot(series, std::string(f.title) + ": " + title, f.y_label, w, h, style), w,
             h, out_dir + "/" + f.file);
    written.push_back(out_dir + "/" + f.file);
  }
  return written;
}

}  // namespace parksim
