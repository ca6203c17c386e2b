#include "parksim/planner/motion/TimeOptimalTiming.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

// Wheel-speed directions closer than this (per component) are one piece.
constexpr double kSameDirection = 1e-9;
// Junction speeds are lowered by this factor while a piece cannot go between them.
constexpr double kLowering = 0.85;
// A bounded number of lowering passes; each lowers at least one junction speed, and a junction
// speed below kZeroSpeed of a step is set to 0, where every piece fits.
constexpr int kMaxPasses = 100000;
constexpr double kZeroSpeed = 1e-3;

double maxAbs(const WheelSpeeds& w) {
  return std::max(std::abs(w.left_radps), std::abs(w.right_radps));
}

WheelSpeeds scaled(const WheelSpeeds& w, double s) { return {w.left_radps * s, w.right_radps * s}; }

// sum_{k < count} min(c + k step, cap), in O(1).
double rampUpSum(double c, double step, double cap, long count) {
  if (count <= 0) return 0.0;
  const long below = std::clamp(static_cast<long>(std::ceil((cap - c) / step)), 0L, count);
  const double b = static_cast<double>(below);
  return b * c + step * b * (b - 1.0) / 2.0 + static_cast<double>(count - below) * cap;
}

// sum_{k < count} max(c - k step, 0), in O(1).
double rampDownSum(double c, double step, long count) {
  if (count <= 0) return 0.0;
  const long above = std::clamp(static_cast<long>(std::ceil(c / step)), 0L, count);
  const double a = static_cast<double>(above);
  return a * c - step * a * (a - 1.0) / 2.0;
}

// The fastest and slowest n-period sequences from e_in to e_out (see profile), as the sums of
// their speeds: hi = sum_i min(e_in + i step, e_out + (n-1-i) step, v_max) and
// lo = sum_i max(e_in - i step, e_out - (n-1-i) step, 0), each split where its two ramps cross.
void bounds(double e_in, double e_out, double v_max, double step, int n, double* lo, double* hi) {
  const double cross_up = 0.5 * ((e_out - e_in) / step + (n - 1));
  const long m_up =
      std::clamp(static_cast<long>(std::floor(cross_up)) + 1, 0L, static_cast<long>(n));
  *hi = rampUpSum(e_in, step, v_max, m_up) + rampUpSum(e_out, step, v_max, n - m_up);
  const double cross_down = 0.5 * ((e_in - e_out) / step + (n - 1));
  const long m_down =
      std::clamp(static_cast<long>(std::floor(cross_down)) + 1, 0L, static_cast<long>(n));
  *lo = rampDownSum(e_in, step, m_down) + rampDownSum(e_out, step, n - m_down);
}

// The fastest speed `i` periods into a soft start from rest: the speed grows by `jstep` more
// each period (a jerk limit), up to `step` per period.
double softRamp(int i, double step, double jstep) {
  // Increments jstep, 2 jstep, ... while below step, then step.
  const int k = std::min(i + 1, static_cast<int>(std::floor(step / jstep)));
  return jstep * k * (k + 1) / 2.0 + (i + 1 - k) * step;
}

// Speed profile of one piece: `n` periods, first at e_in, last at e_out, steps of at most
// `step`, speeds in [0, v_max], summing to `area` (travel / period). The bounds L_i <= u_i <=
// U_i are the slowest and fastest such sequences; their blend hits the area exactly and keeps
// every bound (both have steps within `step`). With `jstep` > 0 the piece starts from rest
// softly: U_i rises as softRamp (and e_in is jstep). False when no such profile has n periods.
bool profile(double e_in, double e_out, double area, double v_max, double step, int n,
             std::vector<double>* out, double jstep = 0.0) {
  if (n == 1) {
    if (std::abs(e_in - e_out) > 1e-12 * std::max(1.0, e_in) ||
        std::abs(e_in - area) > 1e-12 * std::max(1.0, area)) {
      return false;
    }
    if (out) *out = {area};
    return true;
  }
  if (std::abs(e_in - e_out) > (n - 1) * step * (1.0 + 1e-12)) return false;
  // A soft start must reach the speed it leaves with, as a hard one always can.
  if (jstep > 0.0 && softRamp(n - 1, step, jstep) < e_out * (1.0 - 1e-12)) return false;
  auto upper = [&](int i) {
    const double rise = jstep > 0.0 ? softRamp(i, step, jstep) : e_in + i * step;
    return std::min({rise, e_out + (n - 1 - i) * step, v_max});
  };
  double lo = 0.0;
  double hi = 0.0;
  bounds(e_in, e_out, v_max, step, n, &lo, &hi);
  if (jstep > 0.0) {
    hi = 0.0;
    for (int i = 0; i < n; ++i) hi += upper(i);
  }
  // Endpoint speeds are part of both bounds (clamped above, so they must be within v_max).
  const double tol = 1e-12 * std::max(1.0, area);
  if (area < lo - tol || area > hi + tol) return false;
  if (!out) return true;
  const double f = hi - lo > 0.0 ? std::clamp((area - lo) / (hi - lo), 0.0, 1.0) : 0.0;
  out->resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double u_lo = std::max({e_in - i * step, e_out - (n - 1 - i) * step, 0.0});
    (*out)[i] = u_lo + f * (upper(i) - u_lo);
  }
  return true;
}

// Smallest period count with a profile, 0 when none exists.
int periodsFor(double e_in, double e_out, double area, double v_max, double step,
               double jstep = 0.0) {
  // n * v_max >= area is necessary; past ramps of 2 v_max / step and the endpoints' own ramps
  // (a soft start's longer one too) no new count becomes possible.
  int first = std::max(1, static_cast<int>(std::floor(area / v_max)));
  const int soft = jstep > 0.0 ? static_cast<int>(std::ceil(step / jstep)) : 0;
  const int last = static_cast<int>(std::ceil(area / v_max)) +
                   4 * static_cast<int>(std::ceil(v_max / step)) + 2 * soft + 8;
  // The fastest profile's area grows with n: no count below the first whose fastest profile
  // reaches the area works, so bisect for it before trying counts in order.
  const double tol = 1e-12 * std::max(1.0, area);
  int lo = first;
  int hi = last;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    double lo_sum = 0.0;
    double hi_sum = 0.0;
    if (jstep > 0.0) {
      for (int i = 0; i < mid; ++i) {
        hi_sum += std::min({softRamp(i, step, jstep), e_out + (mid - 1 - i) * step, v_max});
      }
    } else {
      bounds(e_in, e_out, v_max, step, mid, &lo_sum, &hi_sum);
    }
    if (mid > 1 && hi_sum >= area - tol) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  if (first > 1 || !profile(e_in, e_out, area, v_max, step, 1, nullptr, jstep))
    first = std::max(first, lo);
  for (int n = first; n <= last; ++n) {
    if (profile(e_in, e_out, area, v_max, step, n, nullptr, jstep)) return n;
  }
  return 0;
}

// Continuous-time minimum to move `travel` from rest to rest, less one period (see header).
double restToRestBound(double travel, const TimingLimits& l) {
  if (travel <= 0.0) return 0.0;
  const double v = l.max_wheel_speed_radps;
  const double a = l.max_wheel_accel_radps2;
  const double t = travel >= v * v / a ? travel / v + v / a : 2.0 * std::sqrt(travel / a);
  return std::max(l.period_s, t - l.period_s);
}

}  // namespace

TimingLimits timingLimits(const RobotDef& robot, double headroom, double period_s,
                          double start_jerk_radps3) {
  if (!(headroom >= 0.0 && headroom < 1.0)) throw Error("timing: headroom must be in [0, 1)");
  if (!(period_s > 0.0)) throw Error("timing: period must be positive");
  if (!(start_jerk_radps3 >= 0.0)) throw Error("timing: start jerk must be >= 0");
  return {(1.0 - headroom) * robot.max_wheel_speed_radps, robot.max_wheel_accel_radps2, period_s,
          start_jerk_radps3};
}

PathPiece pieceOf(const WheelSpeeds& wheels, double duration_s) {
  const double m = maxAbs(wheels);
  if (!(m > 0.0) || !(duration_s > 0.0)) return {};
  return {scaled(wheels, 1.0 / m), m * duration_s};
}

void appendPiece(std::vector<PathPiece>& pieces, const PathPiece& p) {
  if (!(p.travel_rad > 0.0)) return;
  if (!pieces.empty() &&
      std::abs(pieces.back().direction.left_radps - p.direction.left_radps) <= kSameDirection &&
      std::abs(pieces.back().direction.right_radps - p.direction.right_radps) <= kSameDirection) {
    pieces.back().travel_rad += p.travel_rad;
  } else {
    pieces.push_back(p);
  }
}

std::vector<PathPiece> pathPieces(const Trajectory& traj) {
  std::vector<PathPiece> pieces;
  for (std::size_t i = 0; i + 1 < traj.points.size(); ++i) {
    appendPiece(pieces,
                pieceOf(traj.points[i].wheels, traj.points[i + 1].t_s - traj.points[i].t_s));
  }
  return pieces;
}

namespace {

// The junction speeds of the fastest profile along `pieces` and each piece's period count
// (file comment in the header): junction j joins piece j - 1 and piece j, rest before the first
// and after the last. Throws Error on limits that are not positive.
struct Plan {
  std::vector<double> junction;
  std::vector<int> periods;
  double start_jstep = 0.0;  // the first piece's soft start (0: none)
};

Plan planProfile(const std::vector<PathPiece>& pieces, const TimingLimits& limits) {
  const double v_max = limits.max_wheel_speed_radps;
  const double step = limits.max_wheel_accel_radps2 * limits.period_s;
  const double dt = limits.period_s;
  if (!(v_max > 0.0) || !(step > 0.0) || !(dt > 0.0)) {
    throw Error("timing: speed, acceleration and period must be positive");
  }
  const std::size_t k = pieces.size();
  Plan plan;
  plan.start_jstep = limits.start_jerk_radps3 * dt * dt;
  std::vector<double>& e = plan.junction;
  e.resize(k + 1);
  for (std::size_t j = 0; j <= k; ++j) {
    const WheelSpeeds before = j > 0 ? pieces[j - 1].direction : WheelSpeeds{};
    const WheelSpeeds after = j < k ? pieces[j].direction : WheelSpeeds{};
    const double jump =
        maxAbs({before.left_radps - after.left_radps, before.right_radps - after.right_radps});
    e[j] = jump > 0.0 ? std::min(v_max, step / jump) : v_max;
  }
  // A soft start begins one jerk step above rest.
  const double jstep = limits.start_jerk_radps3 * dt * dt;
  if (jstep > 0.0 && k > 0) e[0] = std::min(e[0], jstep);
  auto soft = [&](std::size_t i) { return i == 0 ? jstep : 0.0; };
  std::vector<double> area(k);
  for (std::size_t i = 0; i < k; ++i) area[i] = pieces[i].travel_rad / dt;
  // Only pieces next to a lowered junction need checking again.
  std::vector<char> check(k, 1);
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    bool lowered = false;
    for (std::size_t i = 0; i < k; ++i) {
      if (!check[i]) continue;
      check[i] = 0;
      if (periodsFor(e[i], e[i + 1], area[i], v_max, step, soft(i)) > 0) continue;
      // The soft start's own speed stays: it is already the lowest a start can have.
      const std::size_t j = (e[i] >= e[i + 1] && !(i == 0 && soft(0) > 0.0)) ? i : i + 1;
      e[j] = e[j] > kZeroSpeed * step ? kLowering * e[j] : 0.0;
      check[i] = 1;
      if (j > 0) check[j - 1] = 1;
      if (j < k) check[j] = 1;
      lowered = true;
    }
    if (!lowered) break;
  }
  plan.periods.resize(k);
  for (std::size_t i = 0; i < k; ++i) {
    plan.periods[i] = periodsFor(e[i], e[i + 1], area[i], v_max, step, soft(i));
    if (plan.periods[i] == 0) throw Error("timing: no profile for a piece (internal)");
  }
  return plan;
}

}  // namespace

Trajectory timePieces(const Pose2& start, const std::vector<PathPiece>& pieces,
                      const RobotDef& robot, const TimingLimits& limits) {
  const Plan plan = planProfile(pieces, limits);
  const double v_max = limits.max_wheel_speed_radps;
  const double step = limits.max_wheel_accel_radps2 * limits.period_s;
  const double dt = limits.period_s;
  const std::vector<double>& e = plan.junction;
  Trajectory traj;
  Pose2 pose = start;
  std::vector<double> speeds;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (!profile(e[i], e[i + 1], pieces[i].travel_rad / dt, v_max, step, plan.periods[i], &speeds,
                 i == 0 ? plan.start_jstep : 0.0)) {
      throw Error("timing: no profile for a piece (internal)");
    }
    for (double u : speeds) {
      const WheelSpeeds w = scaled(pieces[i].direction, u);
      traj.points.push_back({static_cast<double>(traj.points.size()) * dt, pose, w});
      pose = integrateExact(pose, toTwist(w, robot), dt);
    }
  }
  traj.points.push_back({static_cast<double>(traj.points.size()) * dt, pose, {}});
  return traj;
}

double timedDuration(const std::vector<PathPiece>& pieces, const TimingLimits& limits) {
  long periods = 0;
  for (int n : planProfile(pieces, limits).periods) periods += n;
  return static_cast<double>(periods) * limits.period_s;
}

Trajectory retime(const Trajectory& traj, const RobotDef& robot, const TimingLimits& limits) {
  if (traj.points.empty()) return traj;
  return timePieces(traj.points.front().pose, pathPieces(traj), robot, limits);
}

double durationLowerBound(const std::vector<PathPiece>& pieces, const TimingLimits& limits) {
  double total = 0.0;
  for (const PathPiece& p : pieces) total += p.travel_rad;
  double bound = restToRestBound(total, limits);
  for (int wheel = 0; wheel < 2; ++wheel) {
    double sum = 0.0;
    double run = 0.0;
    int sign = 0;
    for (const PathPiece& p : pieces) {
      const double c = wheel == 0 ? p.direction.left_radps : p.direction.right_radps;
      const int s = c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
      if (s == 0) continue;
      if (sign != 0 && s != sign) {
        sum += restToRestBound(run, limits);
        run = 0.0;
      }
      sign = s;
      run += std::abs(c) * p.travel_rad;
    }
    sum += restToRestBound(run, limits);
    bound = std::max(bound, sum);
  }
  return bound;
}

Trajectory brakeThenTimePieces(
    const Pose2& from, const WheelSpeeds& from_wheels, const RobotDef& robot,
    const TimingLimits& limits,
    const std::function<std::vector<PathPiece>(const Pose2& at_rest)>& pieces_from) {
  const double dt = limits.period_s;
  const double step = limits.max_wheel_accel_radps2 * dt;
  Trajectory traj;
  Pose2 pose = from;
  WheelSpeeds w = from_wheels;
  while (!(w == WheelSpeeds{})) {
    if (robot.isCar()) {
      // Both wheels slow in proportion: the car keeps its curvature (its steering) braking.
      const double m = maxAbs(w);
      w = m > step ? scaled(w, 1.0 - step / m) : WheelSpeeds{};
    } else {
      w.left_radps -= std::clamp(w.left_radps, -step, step);
      w.right_radps -= std::clamp(w.right_radps, -step, step);
    }
    traj.points.push_back({static_cast<double>(traj.points.size()) * dt, pose, w});
    pose = integrateExact(pose, toTwist(w, robot), dt);
  }
  const Trajectory path = timePieces(pose, pieces_from(pose), robot, limits);
  const double t0 = static_cast<double>(traj.points.size()) * dt;
  for (TrajectoryPoint p : path.points) {
    p.t_s += t0;
    traj.points.push_back(p);
  }
  return traj;
}

SteerResult steerThroughPieces(
    const Pose2& from, const WheelSpeeds& from_wheels, const Pose2& to, SteerMode mode,
    const RobotDef& robot, const TimingLimits& limits, double horizon_s,
    const std::function<std::vector<PathPiece>(const Pose2& at_rest)>& pieces_from) {
  SteerResult result;
  result.trajectory = brakeThenTimePieces(from, from_wheels, robot, limits, pieces_from);
  finishAtTarget(result, to, mode, horizon_s, limits.period_s);
  return result;
}

}  // namespace parksim
