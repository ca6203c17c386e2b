#pragma once
// Test support: whether a car could drive a plan, decided without the planner's code or core's
// geometry (its own arc integration, footprint corners, separating axes and disc test). A car
// (RobotDef::isCar) is a bicycle whose reference point is the middle of its rear axle; a plan's
// rows hold the rear wheels' speeds and the front-wheel angle from their time to the next row's.
// The rules, from the car's own fields of RobotDef:
// - the plan starts at the world's start, at t = 0, wheels straight (steer 0) and at rest;
// - each row's pose is where the previous row's motion, held for its period, leads;
// - it never turns in place: a row that does not move does not turn;
// - a moving row's curvature (yaw rate / speed) is tan(steer) / axle_distance, and within
//   tan(max_steer) / axle_distance;
// - |steer| <= max_steer; the steer changes between rows by at most max_steer_rate times the
//   period (stopped or not: steering while standing takes time too);
// - |speed| <= max_speed; the speed changes between rows by at most max_accel times the
//   period, from rest at the start and to rest at the end (the last row stands still);
// - a gear change stops: between a row driving forward and one driving in reverse lies a row
//   that stands still;
// - the footprint, sampled along each row's exact arc so that no corner moves more than
//   `sample_m` between samples, overlaps no obstacle that blocks the car (touching is allowed),
//   and the reference point stays inside the lot;
// - the plan ends inside the goal region.

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim::testing {

struct CarCheckDef {
  /// Largest distance a footprint corner moves between two sampled poses, m (0: the car's
  /// size / 500, 9 mm for the mid-size car).
  double sample_m = 0.0;
  /// Pose consistency: a row's pose may differ by this from where the previous row leads, m
  /// and rad.
  double pose_tolerance = 1e-6;
  /// Relative slack of the limit checks (rounding of plans timed exactly at a limit).
  double limit_slack = 1e-9;
  /// Speeds below this count as standing still, m/s.
  double still_mps = 1e-9;
};

namespace car_check {

struct Motion {
  double v = 0.0;      // m/s, of the reference point
  double omega = 0.0;  // rad/s
};

inline Motion motionOf(const TrajectoryPoint& p, const RobotDef& car) {
  const double r = car.wheel_radius_m;
  return {0.5 * r * (p.wheels.left_radps + p.wheels.right_radps),
          r * (p.wheels.right_radps - p.wheels.left_radps) / car.wheel_base_m};
}

/// The pose after holding `m` for `dt` from `p`: a straight line or a circular arc.
inline Pose2 drive(const Pose2& p, const Motion& m, double dt) {
  const double turn = m.omega * dt;
  if (std::abs(turn) < 1e-12) {
    return {p.x + m.v * dt * std::cos(p.theta), p.y + m.v * dt * std::sin(p.theta), p.theta + turn};
  }
  const double radius = m.v / m.omega;
  return {p.x + radius * (std::sin(p.theta + turn) - std::sin(p.theta)),
          p.y - radius * (std::cos(p.theta + turn) - std::cos(p.theta)), p.theta + turn};
}

inline double headingGap(double a, double b) {
  const double d = std::remainder(a - b, 2.0 * 3.14159265358979323846);
  return std::abs(d);
}

using Polygon = std::vector<Eigen::Vector2d>;

/// The car's outline at `p`, counter-clockwise.
inline Polygon footprint(const RobotDef& car, const Pose2& p) {
  const double front = car.front_overhang_m;
  const double back = front - car.length_m;
  const double half = 0.5 * car.width_m;
  const Eigen::Vector2d along(std::cos(p.theta), std::sin(p.theta));
  const Eigen::Vector2d across(-along.y(), along.x());
  const Eigen::Vector2d o(p.x, p.y);
  return {o + back * along - half * across, o + front * along - half * across,
          o + front * along + half * across, o + back * along + half * across};
}

/// Interiors of two convex polygons (either winding) overlap by more than `slack` along every
/// edge normal of both.
inline bool convexOverlap(const Polygon& a, const Polygon& b, double slack = 1e-9) {
  for (const Polygon* poly : {&a, &b}) {
    for (std::size_t i = 0; i < poly->size(); ++i) {
      const Eigen::Vector2d e = (*poly)[(i + 1) % poly->size()] - (*poly)[i];
      const Eigen::Vector2d n = Eigen::Vector2d(-e.y(), e.x()).normalized();
      double a_lo = 1e300, a_hi = -1e300, b_lo = 1e300, b_hi = -1e300;
      for (const Eigen::Vector2d& q : a) {
        a_lo = std::min(a_lo, n.dot(q));
        a_hi = std::max(a_hi, n.dot(q));
      }
      for (const Eigen::Vector2d& q : b) {
        b_lo = std::min(b_lo, n.dot(q));
        b_hi = std::max(b_hi, n.dot(q));
      }
      if (std::min(a_hi, b_hi) - std::max(a_lo, b_lo) <= slack) return false;
    }
  }
  return true;
}

/// Distance from `c` to a convex polygon, 0 inside.
inline double distanceTo(const Polygon& poly, const Eigen::Vector2d& c) {
  bool inside = true;
  double best = 1e300;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
    const Eigen::Vector2d ab = b - a;
    if (ab.x() * (c - a).y() - ab.y() * (c - a).x() < 0.0) inside = false;
    const double t = std::clamp((c - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (c - (a + t * ab)).norm());
  }
  return inside ? 0.0 : best;
}

/// The obstacle's convex parts as polygons; a circle as its centre and radius.
struct Shape {
  std::vector<Polygon> parts;
  bool circle = false;
  Eigen::Vector2d center;
  double radius = 0.0;
};

inline Shape shapeOf(const Obstacle& o) {
  Shape s;
  switch (o.shape) {
    case ObstacleShape::kBox: {
      const Eigen::Vector2d ax(std::cos(o.box.yaw), std::sin(o.box.yaw));
      const Eigen::Vector2d ay(-ax.y(), ax.x());
      const Eigen::Vector2d hx = o.box.half_extents.x() * ax;
      const Eigen::Vector2d hy = o.box.half_extents.y() * ay;
      const Eigen::Vector2d c = o.box.center;
      s.parts.push_back({c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy});
      break;
    }
    case ObstacleShape::kCircle:
      s.circle = true;
      s.center = o.box.center;
      s.radius = o.radius_m;
      break;
    case ObstacleShape::kPolygon: s.parts.push_back(o.vertices); break;
    case ObstacleShape::kCompound: s.parts = o.compound->parts; break;
  }
  return s;
}

inline bool overlaps(const Polygon& car, const Shape& s) {
  if (s.circle) return distanceTo(car, s.center) < s.radius - 1e-9;
  for (const Polygon& part : s.parts) {
    if (convexOverlap(car, part)) return true;
  }
  return false;
}

}  // namespace car_check

/// Every rule of the file comment `plan` breaks for the car `scenario.robot`, first broken
/// first, as lines "t = 1.240 s: <quantity> <value> exceeds <limit>"; empty when a car could
/// drive it. Stops after `max_reports`.
inline std::vector<std::string> carPlanViolations(const Scenario& scenario, const Trajectory& plan,
                                                  const CarCheckDef& def = {},
                                                  std::size_t max_reports = 20) {
  using namespace car_check;
  std::vector<std::string> out;
  const RobotDef& car = scenario.robot;
  const std::vector<TrajectoryPoint>& rows = plan.points;
  auto report = [&](double t, const std::string& what) {
    if (out.size() >= max_reports) return;
    std::ostringstream s;
    s.precision(6);
    s << "t = " << t << " s: " << what;
    out.push_back(s.str());
  };
  auto num = [](double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
  };
  if (!car.isCar()) return {"the robot is not a car"};
  if (rows.empty()) return {"the plan has no rows"};
  const double slack = 1.0 + def.limit_slack;
  const double kappa_max = std::tan(car.max_steer_rad) / car.axle_distance_m;
  const Pose2& s0 = rows.front().pose;
  if (rows.front().t_s != 0.0) report(rows.front().t_s, "the plan does not start at t = 0");
  if (std::hypot(s0.x - scenario.start.x, s0.y - scenario.start.y) > def.pose_tolerance ||
      headingGap(s0.theta, scenario.start.theta) > def.pose_tolerance) {
    report(0.0, "the plan starts away from the world's start");
  }
  double steer_before = 0.0;  // wheels straight at the start
  double v_before = 0.0;      // at rest at the start
  int gear_before = 0;        // the last moving row's direction
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const TrajectoryPoint& p = rows[i];
    const bool last = i + 1 == rows.size();
    const double dt = last ? (i > 0 ? p.t_s - rows[i - 1].t_s : 0.0) : rows[i + 1].t_s - p.t_s;
    if (!last && !(dt > 0.0)) report(p.t_s, "times do not increase");
    const Motion m = motionOf(p, car);
    const bool moving = std::abs(m.v) > def.still_mps;
    if (last && (moving || std::abs(m.omega) > 1e-12)) report(p.t_s, "the last row moves");
    if (!moving && std::abs(m.omega) > 1e-12) {
      report(p.t_s, "turns in place at " + num(m.omega) + " rad/s");
    }
    if (moving && !last) {
      const double kappa = m.omega / m.v;
      if (std::abs(kappa) > kappa_max * slack) {
        report(p.t_s,
               "curvature " + num(kappa) + " 1/m exceeds tan(max_steer)/axle " + num(kappa_max));
      }
      const double steered = std::tan(p.steer_rad) / car.axle_distance_m;
      if (std::abs(steered - kappa) > 1e-9 * std::max(1.0, std::abs(kappa))) {
        report(p.t_s,
               "curvature " + num(kappa) + " 1/m is not the steering angle's " + num(steered));
      }
      const int gear = m.v > 0.0 ? 1 : -1;
      if (gear_before != 0 && gear != gear_before && std::abs(v_before) > def.still_mps) {
        report(p.t_s, "the gear changes without a stop");
      }
      gear_before = gear;
    }
    if (std::abs(p.steer_rad) > car.max_steer_rad * slack) {
      report(p.t_s, "steering angle " + num(p.steer_rad) + " rad exceeds max_steer " +
                        num(car.max_steer_rad));
    }
    const double period = i > 0 ? p.t_s - rows[i - 1].t_s : (last ? 0.0 : dt);
    if (std::abs(p.steer_rad - steer_before) > car.max_steer_rate_radps * period * slack + 1e-12) {
      report(p.t_s, "steering rate " + num((p.steer_rad - steer_before) / period) +
                        " rad/s exceeds max_steer_rate " + num(car.max_steer_rate_radps));
    }
    const double v = last ? 0.0 : m.v;
    if (std::abs(v) > car.max_speed_mps * slack) {
      report(p.t_s, "speed " + num(v) + " m/s exceeds max_speed " + num(car.max_speed_mps));
    }
    if (std::abs(v - v_before) > car.max_accel_mps2 * period * slack + 1e-12) {
      report(p.t_s, "acceleration " + num((v - v_before) / period) + " m/s^2 exceeds max_accel " +
                        num(car.max_accel_mps2));
    }
    if (i > 0) {
      const TrajectoryPoint& q = rows[i - 1];
      const Pose2 reached = drive(q.pose, motionOf(q, car), p.t_s - q.t_s);
      if (std::hypot(reached.x - p.pose.x, reached.y - p.pose.y) > def.pose_tolerance ||
          headingGap(reached.theta, p.pose.theta) > def.pose_tolerance) {
        report(p.t_s, "the pose is not where the previous row leads");
      }
    }
    steer_before = p.steer_rad;
    v_before = v;
  }
  // The swept footprint.
  std::vector<Shape> shapes;
  std::vector<std::string> names;
  for (const Obstacle& o : scenario.obstacles) {
    if (!(o.height_m > car.ground_clearance_m)) continue;  // passes under the chassis
    shapes.push_back(shapeOf(o));
    names.push_back(o.name);
  }
  const double sample =
      def.sample_m > 0.0 ? def.sample_m : std::max(car.length_m, car.width_m) / 500;
  const double reach = std::hypot(
      std::max(car.front_overhang_m, car.length_m - car.front_overhang_m), 0.5 * car.width_m);
  auto checkPose = [&](double t, const Pose2& q) {
    const LotBounds& lot = scenario.lot;
    if (!(q.x >= lot.x_min_m && q.x <= lot.x_max_m && q.y >= lot.y_min_m && q.y <= lot.y_max_m)) {
      report(t, "the reference point leaves the lot");
      return false;
    }
    const Polygon fp = footprint(car, q);
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      if (overlaps(fp, shapes[k])) {
        report(t, "the footprint overlaps " + names[k]);
        return false;
      }
    }
    return true;
  };
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    const TrajectoryPoint& p = rows[i];
    const double dt = rows[i + 1].t_s - p.t_s;
    const Motion m = motionOf(p, car);
    const double travel = (std::abs(m.v) + std::abs(m.omega) * reach) * dt;
    const int n = std::max(1, static_cast<int>(std::ceil(travel / sample)));
    bool ok = true;
    for (int k = 0; k < n && ok; ++k)
      ok = checkPose(p.t_s + dt * k / n, drive(p.pose, m, dt * k / n));
    if (!ok) break;
  }
  checkPose(rows.back().t_s, rows.back().pose);
  const GoalRegion& goal = scenario.goal;
  const Pose2& end = rows.back().pose;
  double heading = headingGap(end.theta, goal.pose.theta);
  if (goal.either_heading) heading = std::min(heading, 3.14159265358979323846 - heading);
  const double pos = std::hypot(end.x - goal.pose.x, end.y - goal.pose.y);
  if (pos > goal.position_tolerance_m || heading > goal.heading_tolerance_rad) {
    report(rows.back().t_s, "the plan ends " + num(pos) + " m / " + num(heading) +
                                " rad from the goal, outside its tolerance");
  }
  return out;
}

/// Counts what a plan does: its gear changes (stops between forward and reverse driving).
inline int carGearChanges(const RobotDef& car, const Trajectory& plan) {
  int changes = 0;
  int gear = 0;
  for (const TrajectoryPoint& p : plan.points) {
    const double v = car_check::motionOf(p, car).v;
    if (std::abs(v) <= 1e-9) continue;
    const int g = v > 0.0 ? 1 : -1;
    if (gear != 0 && g != gear) ++changes;
    gear = g;
  }
  return changes;
}

}  // namespace parksim::testing
