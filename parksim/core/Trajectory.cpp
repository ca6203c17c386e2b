#include "parksim/core/Trajectory.h"

#include <cmath>
#include <iterator>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/Csv.h"
#include "parksim/core/Error.h"
#include "parksim/core/NumberFormat.h"

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
  out.reserve(out.size() + traj.points.size() * 160);
  for (const TrajectoryPoint& p : traj.points) {
    const Twist tw = toTwist(p.wheels, robot);
    const double values[] = {
        p.t_s,    p.pose.x,      p.pose.y, p.pose.theta, p.wheels.left_radps, p.wheels.right_radps,
        tw.v_mps, tw.omega_radps};
    for (std::size_t i = 0; i < std::size(values); ++i) {
      if (i > 0) out += ',';
      appendRoundTrip(out, values[i]);
    }
    out += '\n';
  }
  writeFileAtomically(path, out);
}

Trajectory readTrajectoryCsv(const std::string& path) {
  const CsvTable csv = readCsvFile(path);
  const std::size_t t = csv.column("t");
  const std::size_t x = csv.column("x");
  const std::size_t y = csv.column("y");
  const std::size_t theta = csv.column("theta");
  const std::size_t left = csv.column("omega_left");
  const std::size_t right = csv.column("omega_right");
  Trajectory traj;
  for (const CsvTable::Row& row : csv.rows()) {
    TrajectoryPoint p;
    p.t_s = csv.number(row, t);
    p.pose = {csv.number(row, x), csv.number(row, y), csv.number(row, theta)};
    p.wheels = {csv.number(row, left), csv.number(row, right)};
    if (!traj.points.empty() && !(p.t_s > traj.points.back().t_s)) {
      throw Error(path + ":" + std::to_string(row.line) + ": column 't': time does not increase");
    }
    traj.points.push_back(p);
  }
  if (traj.points.empty()) throw Error(path + ": trajectory has no rows");
  return traj;
}

}  // namespace parksim
