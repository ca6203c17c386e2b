#include "parksim/sweep/spec/EpisodeParams.h"

#include <cstdio>

#include "parksim/sweep/spec/SetValues.h"

namespace parksim {
namespace {

std::string number(double v) { return nlohmann::json(v).dump(); }

std::string offset(const PoseOffset& o) {
  return number(o.dx_m) + "," + number(o.dy_m) + "," + number(o.dyaw_deg);
}

}  // namespace

std::string canonicalString(const EpisodeParams& p) {
  std::string s = "ids=" + std::to_string(kEpisodeIdFormat);
  s += ";world=" + p.world + ";planner=" + p.planner + ";steering=" + p.steering;
  s += std::string(";smooth=") + (p.smooth ? "1" : "0");
  s += ";seed=" + std::to_string(p.seed);
  s +=
      ";max_iterations=" + (p.max_iterations == kAutoIterations ? std::string("auto")
                                                                : std::to_string(p.max_iterations));
  s += ";tracking=" + p.tracking + ";timing=" + p.timing + ";realism=" + p.realism;
  s += ";noise_seed=" + std::to_string(p.noise_seed);
  s += ";start_offset=" + offset(p.start_offset) + ";goal_offset=" + offset(p.goal_offset);
  // Extension keys: only when set (kExtensionKeys).
  if (p.sample) s += ";sample=" + std::to_string(*p.sample);
  if (p.controller != kDefaultController) s += ";controller=" + p.controller;
  for (const auto& [path, value] : p.world_set) s += ";set." + path + "=" + value;
  for (const auto& [name, value] : p.planner_params) s += ";planner." + name + "=" + value;
  for (const auto& [name, value] : p.controller_params) s += ";controller." + name + "=" + value;
  return s;
}

std::string episodeId(const EpisodeParams& params) {
  return hex16(fnv1a64(canonicalString(params)));
}

void appendParamColumns(const EpisodeParams& p, nlohmann::ordered_json& row) {
  row["world"] = p.world;
  row["world_file"] = p.world_file;
  row["planner"] = p.planner;
  row["steering"] = p.steering;
  row["smooth"] = p.smooth;
  row["seed"] = p.seed;
  row["max_iterations"] = p.max_iterations;
  row["tracking"] = p.tracking;
  row["controller"] = p.controller;
  row["timing"] = p.timing;
  row["realism"] = p.realism;
  row["noise_seed"] = p.noise_seed;
  row["start_dx_m"] = p.start_offset.dx_m;
  row["start_dy_m"] = p.start_offset.dy_m;
  row["start_dyaw_deg"] = p.start_offset.dyaw_deg;
  row["goal_dx_m"] = p.goal_offset.dx_m;
  row["goal_dy_m"] = p.goal_offset.dy_m;
  row["goal_dyaw_deg"] = p.goal_offset.dyaw_deg;
  if (p.sample) row["sample"] = *p.sample;
  for (const auto& [path, value] : p.world_set) row[path] = setValueJson(value);
  for (const auto& [name, value] : p.planner_params) row["planner." + name] = setValueJson(value);
  for (const auto& [name, value] : p.controller_params) {
    row["controller." + name] = setValueJson(value);
  }
}

std::vector<std::string> setColumnsOf(const EpisodeParams& p) {
  std::vector<std::string> columns;
  for (const auto& [path, value] : p.world_set) columns.push_back(path);
  for (const auto& [name, value] : p.planner_params) columns.push_back("planner." + name);
  for (const auto& [name, value] : p.controller_params) columns.push_back("controller." + name);
  return columns;
}

}  // namespace parksim
