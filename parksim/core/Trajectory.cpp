#include "parksim/core/Trajectory.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"

namespace parksim {

double Trajectory::pathLength(const RobotDef& robot) const {
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double dt = points[i + 1].t_s - points[i].t_s;
    length += std::abs(toTwist(points[i].wheels, robot).v_mps) * dt;
  }
  return length;
}

int Trajectory::cusps(const RobotDef& robot) const {
  int count = 0;
  int last_sign = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double v = toTwist(points[i].wheels, robot).v_mps;
    // Speeds below 0.1 mm/s are turning in place, not a direction.
    const int sign = v > 1e-4 ? 1 : (v < -1e-4 ? -1 : 0);
    if (sign != 0) {
      if (last_sign != 0 && sign != last_sign) ++count;
      last_sign = sign;
    }
  }
  return count;
}

void Trajectory::append(const Trajectory& tail) {
  if (tail.points.empty()) return;
  if (points.empty()) {
    points = tail.points;
    return;
  }
  const double t0 = points.back().t_s - tail.points.front().t_s;
  points.pop_back();  // the junction pose is the tail's first point, which carries its wheels
  for (TrajectoryPoint p : tail.points) {
    p.t_s += t0;
    points.push_back(p);
  }
}

void writeTrajectoryCsv(const std::string& path, const Trajectory& traj, const RobotDef& robot) {
  std::string out = "t,x,y,theta,omega_left,omega_right,v,omega\n";
  char line[320];
  for (const TrajectoryPoint& p : traj.points) {
    const Twist tw = toTwist(p.wheels, robot);
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", p.t_s,
                  p.pose.x, p.pose.y, p.pose.theta, p.wheels.left_radps, p.wheels.right_radps,
                  tw.v_mps, tw.omega_radps);
    out += line;
  }
  writeFileAtomically(path, out);
}

Trajectory readTrajectoryCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open trajectory file");
  std::string line;
  if (!std::getline(in, line)) throw Error(path + ":1: empty trajectory file (expected a header)");
  std::map<std::string, int> column;
  {
    std::stringstream ss(line);
    std::string name;
    int i = 0;
    while (std::getline(ss, name, ',')) {
      if (!name.empty() && name.back() == '\r') name.pop_back();
      column[name] = i++;
    }
  }
  const char* required[] = {"t", "x", "y", "theta", "omega_left", "omega_right"};
  for (const char* name : required) {
    if (!column.count(name)) throw Error(path + ":1: header lacks column '" + name + "'");
  }
  Trajectory traj;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    auto get = [&](const char* name) {
      const int idx = column[name];
      const std::string where = path + ":" + std::to_string(line_no) + ": column '" + name + "'";
      if (idx >= static_cast<int>(cells.size())) throw Error(where + ": missing value");
      const std::string& s = cells[idx];
      double value = 0.0;
      const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
      if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) {
        throw Error(where + ": '" + s + "' is not a finite number");
      }
      return value;
    };
    TrajectoryPoint p;
    p.t_s = get("t");
    p.pose = {get("x"), get("y"), get("theta")};
    p.wheels = {get("omega_left"), get("omega_right")};
    if (!traj.points.empty() && !(p.t_s > traj.points.back().t_s)) {
      throw Error(path + ":" + std::to_string(line_no) + ": column 't': time does not increase");
    }
    traj.points.push_back(p);
  }
  if (traj.points.empty()) throw Error(path + ": trajectory has no rows");
  return traj;
}

}  // namespace parksim
