#include "parksim/report/Report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/FileName.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/stats/Quantile.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/report/BoxPlot.h"
#include "parksim/report/ParameterPlot.h"
#include "parksim/report/SuccessMatrix.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/results/tables/ResultsFile.h"
#include "parksim/sweep/spec/EpisodeParams.h"

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
  std::snprintf(buf, sizeof buf, format, quantileSorted7(s, 0.5), quantileSorted7(s, 0.95));
  return buf;
}

std::string median(const std::vector<double>& v, const char* format) {
  if (v.empty()) return "-";
  std::vector<double> s = v;
  std::sort(s.begin(), s.end());
  char buf[64];
  std::snprintf(buf, sizeof buf, format, quantileSorted7(s, 0.5));
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
  return nlohmann::json(quantileSorted7(s, q)).dump();
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

// " NAME=value" for each of the row's `prefix`NAME columns (a component's own parameters), the
// name shown after `shown`: " controller.gain=2".
void appendParams(std::string& s, const Json& row, const std::string& prefix,
                  const std::string& shown) {
  for (const auto& [key, value] : row.items()) {
    if (key.rfind(prefix, 0) != 0) continue;
    s += ' ';
    s += shown;
    s += key.substr(prefix.size());
    s += '=';
    s += value.is_string() ? value.get<std::string>() : value.dump();
  }
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
  // Two controllers of one sweep are two groups (the planner's label, as their rows'
  // steering and tracking are), and so are two entries of one planner or controller with other
  // parameters (planner.NAME, controller.NAME columns).
  appendParams(s, row, "planner.", "");
  const std::string controller = str(row, "controller", defaults.controller.c_str());
  if (!controller.empty() && controller != defaults.controller) {
    s += " controller=";
    s += controller;
  }
  appendParams(s, row, "controller.", "controller.");
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

namespace {

// 95% Wilson score interval of k successes in n (Wilson 1927): unlike the normal
// approximation, it stays in [0, 1] and is not empty at k = 0 or k = n.
std::pair<double, double> wilson(int k, int n) {
  if (n <= 0) return {0.0, 1.0};
  constexpr double z = 1.959963984540054;
  const double p = static_cast<double>(k) / n;
  const double denom = 1.0 + z * z / n;
  const double centre = (p + z * z / (2.0 * n)) / denom;
  const double half = z * std::sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / denom;
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

// Parameters whose variation is replication (isReplicateKey), not a question asked, and
// world_file (world names it): not studied.
bool studied(std::string_view key) {
  return key != "episode_id" && key != "world_file" && !isReplicateKey(key);
}

// The candidate columns: the record's parameter fields and the set: columns of the rows.
std::vector<std::string> parameterColumns(const std::vector<Json>& rows) {
  std::vector<std::string> columns;
  for (const EpisodeField& f : episodeFields()) {
    if (f.group == FieldGroup::kParameter && studied(f.key)) columns.emplace_back(f.key);
  }
  std::set<std::string, std::less<>> set_keys;
  for (const Json& row : rows) addSetKeys(row, set_keys);
  columns.insert(columns.end(), set_keys.begin(), set_keys.end());
  return columns;
}

std::string valueText(const Json* v) {
  if (v == nullptr || v->is_null()) return "(none)";
  return v->is_string() ? v->get<std::string>() : v->dump();
}

void addEpisode(ParameterLevel& level, const Json& row) {
  ++level.episodes;
  if (flag(row, "met_tolerance")) ++level.met;
  double v = 0.0;
  if (number(row, "max_pos_err_m", v)) level.max_err_mm.push_back(1e3 * v);
  if (number(row, "goal_pos_err_m", v)) level.goal_err_mm.push_back(1e3 * v);
}

void finish(ParameterLevel& level) {
  std::tie(level.met_low, level.met_high) = wilson(level.met, level.episodes);
}

// One parameter's levels, or nothing when it took one value.
std::optional<ParameterStudy> studyOf(const std::vector<Json>& rows, const std::string& column) {
  bool numeric = true;
  std::map<std::string, std::vector<const Json*>> by_text;
  std::map<double, std::vector<const Json*>> by_number;
  for (const Json& row : rows) {
    const auto it = row.find(column);
    const Json* v = it != row.end() && !it->is_null() ? &*it : nullptr;
    by_text[valueText(v)].push_back(&row);
    if (v != nullptr && v->is_number()) {
      by_number[v->get<double>()].push_back(&row);
    } else {
      numeric = false;
    }
  }
  if (by_text.size() < 2) return std::nullopt;
  ParameterStudy study;
  study.parameter = column;
  study.numeric = numeric;
  if (!numeric) {
    for (const auto& [text, members] : by_text) {
      ParameterLevel level;
      level.label = text;
      level.x = static_cast<double>(study.levels.size());
      for (const Json* row : members) addEpisode(level, *row);
      finish(level);
      study.levels.push_back(std::move(level));
    }
    return study;
  }
  study.binned = by_number.size() > kMaxParameterLevels;
  // Equal-count bins of the values in order (a value's episodes stay in one bin).
  const std::size_t bins = study.binned ? 10 : by_number.size();
  std::size_t done = 0;
  auto it = by_number.begin();
  for (std::size_t b = 0; b < bins && it != by_number.end(); ++b) {
    const std::size_t until = rows.size() * (b + 1) / bins;
    ParameterLevel level;
    const double lo = it->first;
    double hi = lo;
    double sum = 0.0;
    do {
      hi = it->first;
      for (const Json* row : it->second) addEpisode(level, *row);
      sum += it->first * static_cast<double>(it->second.size());
      done += it->second.size();
      ++it;
    } while (study.binned && it != by_number.end() && (done < until || b + 1 == bins));
    level.x = study.binned ? sum / level.episodes : lo;
    level.label = study.binned ? "[" + formatGeneral(lo, 4) + ", " + formatGeneral(hi, 4) + "]"
                               : formatShortest(lo);
    finish(level);
    study.levels.push_back(std::move(level));
  }
  return study;
}

std::string quantiles(const std::vector<double>& v) { return medianP95(v, "%.3f / %.3f"); }

}  // namespace

std::vector<ParameterStudy> parameterStudies(const std::vector<Json>& rows) {
  std::vector<ParameterStudy> out;
  for (const std::string& column : parameterColumns(rows)) {
    if (std::optional<ParameterStudy> s = studyOf(rows, column)) out.push_back(std::move(*s));
  }
  std::sort(out.begin(), out.end(), [](const ParameterStudy& a, const ParameterStudy& b) {
    return a.parameter < b.parameter;
  });
  return out;
}

std::optional<ParameterBoundary> parameterBoundary(const std::vector<Json>& rows,
                                                   const ParameterStudy& study) {
  if (!study.numeric) return std::nullopt;
  // Every distinct value, met when all its episodes met their tolerance (bins aside).
  std::map<double, bool> all_met;
  for (const Json& row : rows) {
    double v = 0.0;
    if (!number(row, study.parameter.c_str(), v)) continue;
    const auto [it, inserted] = all_met.emplace(v, true);
    it->second = it->second && flag(row, "met_tolerance");
  }
  std::vector<std::pair<double, bool>> values(all_met.begin(), all_met.end());
  // A boundary needs one end where every episode met and the other where some did not.
  if (values.size() < 2 || values.front().second == values.back().second) return std::nullopt;
  // Walked from the end that met.
  if (!values.front().second) std::reverse(values.begin(), values.end());
  std::size_t k = 1;
  while (k < values.size() && values[k].second) ++k;
  if (k == values.size()) return std::nullopt;
  ParameterBoundary b;
  b.parameter = study.parameter;
  b.last_met = values[k - 1].first;
  b.first_failed = values[k].first;
  for (std::size_t i = k; i < values.size(); ++i) b.monotone = b.monotone && !values[i].second;
  return b;
}

std::string parametersMarkdown(const std::vector<ParameterStudy>& studies,
                               const std::optional<ParameterBoundary>& boundary) {
  std::string s;
  for (const ParameterStudy& st : studies) {
    s += "\n### " + st.parameter + "\n\n";
    if (st.binned) s += "Its values in 10 bins of about equal counts.\n\n";
    s += "| " + st.parameter +
         " | episodes | met tolerance | 95% interval | max tracking error, median / p95 (mm) | "
         "goal error, median / p95 (mm) |\n|---|---:|---:|---:|---:|---:|\n";
    for (const ParameterLevel& l : st.levels) {
      char interval[64];
      std::snprintf(interval, sizeof interval, "%.0f%% - %.0f%%", 100.0 * l.met_low,
                    100.0 * l.met_high);
      s += "| " + l.label + " | " + std::to_string(l.episodes) + " | " +
           percent(l.met, l.episodes) + " | " + interval + " | " + quantiles(l.max_err_mm) + " | " +
           quantiles(l.goal_err_mm) + " |\n";
    }
  }
  if (boundary) {
    const ParameterBoundary& b = *boundary;
    const bool rising = b.first_failed > b.last_met;
    s += "\n**Boundary** (" + b.parameter + "): every episode met its tolerance " +
         (rising ? "up to " : "down to ") + formatShortest(b.last_met) + "; from " +
         formatShortest(b.first_failed) + (rising ? " up" : " down") + " some did not" +
         (b.monotone ? " (at every value past it)" : " (further on, some values meet again)") +
         ".\n";
  }
  return s;
}

std::string parametersCsv(const std::vector<ParameterStudy>& studies) {
  std::string s =
      "parameter,value,x,episodes,met_tolerance,met_low,met_high,max_err_mm_median,"
      "max_err_mm_p95,goal_err_mm_median,goal_err_mm_p95\n";
  const auto quoted = [](const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q = "\"";
    for (const char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  for (const ParameterStudy& st : studies) {
    for (const ParameterLevel& l : st.levels) {
      s += quoted(st.parameter) + "," + quoted(l.label) + "," + formatShortest(l.x) + "," +
           std::to_string(l.episodes) + "," + std::to_string(l.met) + "," +
           formatShortest(l.met_low) + "," + formatShortest(l.met_high) + "," +
           csvNumber(l.max_err_mm, 0.5) + "," + csvNumber(l.max_err_mm, 0.95) + "," +
           csvNumber(l.goal_err_mm, 0.5) + "," + csvNumber(l.goal_err_mm, 0.95) + "\n";
    }
  }
  return s;
}

namespace {

// The file name of a parameter's plot: parameter_<column>.png, the column made safe and apart
// from the others (fileStemOf).
std::string plotFile(const std::string& parameter) {
  return "parameter_" + fileStemOf(parameter) + ".png";
}

std::optional<double> quantileOf(const std::vector<double>& v, double q) {
  if (v.empty()) return std::nullopt;
  std::vector<double> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  return quantileSorted7(sorted, q);
}

}  // namespace

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

  const std::vector<ParameterStudy> studies = parameterStudies(rows);
  if (studies.empty()) return written;
  const std::optional<ParameterBoundary> boundary =
      studies.size() == 1 ? parameterBoundary(rows, studies.front()) : std::nullopt;
  std::string summary = "# " + title + "\n\n" + std::to_string(rows.size()) + " episodes.\n\n" +
                        summaryMarkdown(groups) + "\n## Per parameter\n" +
                        parametersMarkdown(studies, boundary);
  writeFileAtomically(out_dir + "/summary.md", summary);
  writeFileAtomically(out_dir + "/parameters.csv", parametersCsv(studies));
  written.push_back(out_dir + "/parameters.csv");
  for (const ParameterStudy& st : studies) {
    ParameterPlotInput in;
    in.parameter = st.parameter;
    in.numeric = st.numeric;
    for (const ParameterLevel& l : st.levels) {
      in.levels.push_back({l.x, l.label, l.episodes > 0 ? double(l.met) / l.episodes : 0.0,
                           l.met_low, l.met_high, quantileOf(l.max_err_mm, 0.5),
                           quantileOf(l.max_err_mm, 0.95)});
    }
    if (boundary && boundary->parameter == st.parameter) {
      in.boundary_x = 0.5 * (boundary->last_met + boundary->first_failed);
    }
    const std::string path = out_dir + "/" + plotFile(st.parameter);
    renderTo(buildParameterPlot(in, st.parameter + ": " + title, w, h, style), w, h, path);
    written.push_back(path);
  }
  return written;
}

}  // namespace parksim
