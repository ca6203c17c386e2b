#include "parksim/planner/motion/CarTiming.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

namespace {

// The profile accelerates at this share of the limit and passes clothoids at this share of the
// speed that turns the steering at its rate limit: rows average the profile over a period, and
// the margins keep their steps within the limits whatever the averaging does.
constexpr double kAccelShare = 0.98;
constexpr double kSteerShare = 0.9;
// A run's profile is computed on cells of about this length, m, and at most this many.
constexpr double kCell_m = 0.005;
constexpr long kMaxCells = 400000;
// A clothoid whose rows still steer too fast is passed this much slower, up to this many times.
constexpr double kSlower = 0.8;
constexpr int kMaxSlowdowns = 20;
// Rows shorter than this take the curvature at their middle, m.
constexpr double kShortRow_m = 1e-6;

// A run: sections driven one way without a stop, from rest to rest.
struct Run {
  std::vector<CarSection> sections;
  std::vector<double> begin;  // distance from the run's start to each section's start, m
  std::vector<double> turn;   // integrated curvature up to each section's start, rad
  double length = 0.0;
  int direction = 1;

  // The integrated curvature from the run's start to distance s, rad (signed as curvature).
  double integrated(double s) const {
    const std::size_t k = sectionAt(s);
    const CarSection& c = sections[k];
    const double u = std::clamp(s - begin[k], 0.0, c.length_m);
    const double slope = (c.kappa_end - c.kappa_begin) / c.length_m;
    return turn[k] + c.kappa_begin * u + 0.5 * slope * u * u;
  }
  double curvatureAt(double s) const {
    const std::size_t k = sectionAt(s);
    const CarSection& c = sections[k];
    const double u = std::clamp(s - begin[k], 0.0, c.length_m);
    return c.kappa_begin + (c.kappa_end - c.kappa_begin) * u / c.length_m;
  }
  // The least and the largest curvature between distances a <= b: at the ends or where
  // sections join (curvature is linear along each).
  std::pair<double, double> curvatureRange(double a, double b) const {
    double least = std::min(curvatureAt(a), curvatureAt(b));
    double most = std::max(curvatureAt(a), curvatureAt(b));
    for (std::size_t k = sectionAt(a) + 1; k < sections.size() && begin[k] < b; ++k) {
      least = std::min(least, sections[k].kappa_begin);
      most = std::max(most, sections[k].kappa_begin);
    }
    return {least, most};
  }
  std::size_t sectionAt(double s) const {
    const auto it = std::upper_bound(begin.begin(), begin.end(), s);
    return it == begin.begin() ? 0 : static_cast<std::size_t>(it - begin.begin()) - 1;
  }
};

std::vector<Run> runsOf(const std::vector<CarSection>& sections) {
  std::vector<Run> runs;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const CarSection& s = sections[i];
    if (!(s.length_m > 0.0)) continue;
    if (runs.empty() || stopsBetween(runs.back().sections.back(), s)) {
      runs.emplace_back();
      runs.back().direction = s.direction;
    }
    Run& r = runs.back();
    r.turn.push_back(r.sections.empty() ? 0.0 : r.integrated(r.length));
    r.begin.push_back(r.length);
    r.sections.push_back(s);
    r.length += s.length_m;
  }
  return runs;
}

// The fastest speed profile along a run under per-section caps (file comment), on cells.
struct Profile {
  double cell = 0.0;
  std::vector<double> speed;  // at the cells' ends, m/s
  std::vector<double> time;   // from the run's start to the cells' ends, s

  double duration() const { return time.back(); }

  // Distance driven by time t (clamped to the run), m.
  double distanceAt(double t, std::size_t& cursor) const {
    const std::size_t n = time.size() - 1;
    if (t >= time[n]) return cell * static_cast<double>(n);
    while (cursor + 1 < n && time[cursor + 1] <= t) ++cursor;
    const double va = speed[cursor];
    const double vb = speed[cursor + 1];
    const double accel = (vb * vb - va * va) / (2.0 * cell);
    const double tau = t - time[cursor];
    const double d = std::clamp(va * tau + 0.5 * accel * tau * tau, 0.0, cell);
    return cell * static_cast<double>(cursor) + d;
  }
};

// How fast the steering angle changes with the distance driven along a clothoid from kappa_a to
// kappa_b of length `length`, at its steepest, rad/m: d steer / ds = L kappa' / (1 + L^2
// kappa^2), steepest where |kappa| is least.
double steerSlope(double kappa_a, double kappa_b, double length, const RobotDef& car) {
  const double least =
      kappa_a * kappa_b <= 0.0 ? 0.0 : std::min(std::abs(kappa_a), std::abs(kappa_b));
  const double axle = car.axle_distance_m;
  return axle * std::abs(kappa_b - kappa_a) / length / (1.0 + axle * axle * least * least);
}

// Each section's speed cap, m/s: the speed limit, the rear wheels' on its sharpest curvature,
// and on a clothoid the steering rate's, times `scale`.
double sectionCap(const CarSection& s, const RobotDef& car, const CarLimits& l, double scale) {
  const double sharpest = std::max(std::abs(s.kappa_begin), std::abs(s.kappa_end));
  double cap = std::min(l.max_speed_mps, l.max_wheel_speed_radps * car.wheel_radius_m /
                                             (1.0 + 0.5 * car.wheel_base_m * sharpest));
  if (!s.constantCurvature()) {
    cap = std::min(cap, kSteerShare * l.max_steer_rate_radps /
                            steerSlope(s.kappa_begin, s.kappa_end, s.length_m, car));
  }
  return scale * cap;
}

Profile profileOf(const Run& run, const RobotDef& car, const CarLimits& l,
                  const std::vector<double>& scale) {
  Profile p;
  const long n = std::clamp(static_cast<long>(std::ceil(run.length / kCell_m)), 16L, kMaxCells);
  p.cell = run.length / static_cast<double>(n);
  std::vector<double> cap2(static_cast<std::size_t>(n + 1), l.max_speed_mps * l.max_speed_mps);
  // Rows straddle sections: a section's cap holds a row's length (and a cell) beyond its ends.
  const double reach = l.max_speed_mps * l.period_s + p.cell;
  for (std::size_t k = 0; k < run.sections.size(); ++k) {
    const double cap = sectionCap(run.sections[k], car, l, scale[k]);
    const double c2 = cap * cap;
    const long i0 = std::max(0L, static_cast<long>(std::floor((run.begin[k] - reach) / p.cell)));
    const long i1 = std::min(
        n,
        static_cast<long>(std::ceil((run.begin[k] + run.sections[k].length_m + reach) / p.cell)));
    for (long i = i0; i <= i1; ++i) cap2[i] = std::min(cap2[i], c2);
  }
  const double twice_accel_cell = 2.0 * kAccelShare * l.max_accel_mps2 * p.cell;
  std::vector<double> v2(cap2.size());
  v2[0] = 0.0;
  for (std::size_t i = 1; i < v2.size(); ++i)
    v2[i] = std::min(cap2[i], v2[i - 1] + twice_accel_cell);
  v2.back() = 0.0;
  for (std::size_t i = v2.size() - 1; i-- > 0;)
    v2[i] = std::min(v2[i], v2[i + 1] + twice_accel_cell);
  p.speed.resize(v2.size());
  p.time.resize(v2.size());
  for (std::size_t i = 0; i < v2.size(); ++i) p.speed[i] = std::sqrt(v2[i]);
  p.time[0] = 0.0;
  for (std::size_t i = 1; i < v2.size(); ++i) {
    p.time[i] = p.time[i - 1] + 2.0 * p.cell / (p.speed[i - 1] + p.speed[i]);
  }
  return p;
}

long periodsOf(const Profile& p, double period_s) {
  return std::max(1L, static_cast<long>(std::ceil(p.duration() / period_s - 1e-9)));
}

// Standing rows that steer from `from` to `to` at the rate limit (at least `least` rows).
long steeringRows(double from, double to, const CarLimits& l, long least) {
  const double step = l.max_steer_rate_radps * l.period_s;
  return std::max(least, static_cast<long>(std::ceil(std::abs(to - from) / step - 1e-9)));
}

void checkLimits(const CarLimits& l) {
  if (!(l.max_speed_mps > 0.0) || !(l.max_accel_mps2 > 0.0) || !(l.max_steer_rad > 0.0) ||
      !(l.max_steer_rate_radps > 0.0) || !(l.max_wheel_speed_radps > 0.0) || !(l.period_s > 0.0)) {
    throw Error("car timing: speed, acceleration, steering, steering rate and period must be > 0");
  }
}

// A run's rows: the distance each drives and its mean curvature.
struct RunRows {
  std::vector<double> distance;  // m, >= 0
  std::vector<double> kappa;     // 1/m
};

RunRows rowsOf(const Run& run, const Profile& p, double period_s) {
  const long n = periodsOf(p, period_s);
  RunRows rows;
  std::size_t cursor = 0;
  double s0 = 0.0;
  for (long i = 0; i < n; ++i) {
    const double s1 = i + 1 == n ? run.length : p.distanceAt((i + 1) * period_s, cursor);
    const double d = std::max(0.0, s1 - s0);
    rows.distance.push_back(d);
    // The mean curvature, within the curvatures the row passes (a difference of integrals over
    // a row of micrometres is mostly rounding: that row takes its middle's).
    const double kappa = d > kShortRow_m ? (run.integrated(s1) - run.integrated(s0)) / d
                                         : run.curvatureAt(0.5 * (s0 + s1));
    const auto [least, most] = run.curvatureRange(s0, s1);
    rows.kappa.push_back(std::clamp(kappa, least, most));
    s0 = std::max(s0, s1);
  }
  return rows;
}

}  // namespace

CarLimits carLimits(const RobotDef& car, double headroom, double period_s) {
  if (!(headroom >= 0.0 && headroom < 1.0)) throw Error("car timing: headroom must be in [0, 1)");
  CarLimits l;
  l.max_speed_mps = car.max_speed_mps;
  l.max_accel_mps2 = car.max_accel_mps2;
  l.max_steer_rad = car.max_steer_rad;
  l.max_steer_rate_radps = (1.0 - headroom) * car.max_steer_rate_radps;
  l.max_wheel_speed_radps = car.max_wheel_speed_radps;
  l.period_s = period_s;
  checkLimits(l);
  return l;
}

double clothoidHalfLength(double kappa_a, double kappa_b, double speed_mps, const RobotDef& car,
                          const CarLimits& l) {
  // The cap of a clothoid of length 2h is kSteerShare rate / slope, the slope falling as 1 / h.
  return 0.5 * speed_mps * steerSlope(kappa_a, kappa_b, 1.0, car) /
         (kSteerShare * l.max_steer_rate_radps);
}

double steerOf(double kappa, const RobotDef& car) { return std::atan(car.axle_distance_m * kappa); }

Trajectory timeCarPath(const Pose2& start, const std::vector<CarSection>& sections,
                       const RobotDef& car, const CarLimits& l) {
  checkLimits(l);
  const double kappa_max = std::tan(l.max_steer_rad) / car.axle_distance_m;
  for (const CarSection& s : sections) {
    if (std::max(std::abs(s.kappa_begin), std::abs(s.kappa_end)) > kappa_max * (1.0 + 1e-9)) {
      throw Error("car timing: a section is sharper than the car's steering limit");
    }
  }
  const double dt = l.period_s;
  const double steer_step = l.max_steer_rate_radps * dt;
  Trajectory traj;
  Pose2 pose = start;
  double steer = 0.0;  // the car starts with its wheels straight
  auto push = [&](double v, double kappa, double steer_rad) {
    const Twist twist{v, v * kappa};
    traj.points.push_back(
        {static_cast<double>(traj.points.size()) * dt, pose, toWheelSpeeds(twist, car), steer_rad});
    pose = integrateExact(pose, twist, dt);
  };
  const std::vector<Run> runs = runsOf(sections);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Run& run = runs[r];
    std::vector<double> scale(run.sections.size(), 1.0);
    RunRows rows;
    for (int attempt = 0;; ++attempt) {
      rows = rowsOf(run, profileOf(run, car, l, scale), dt);
      // Rows whose steering steps too fast slow the sections under them down.
      bool slowed = false;
      double s = 0.0;
      for (std::size_t i = 0; i + 1 < rows.kappa.size(); ++i) {
        const double step = std::abs(steerOf(rows.kappa[i + 1], car) - steerOf(rows.kappa[i], car));
        if (step > steer_step * (1.0 + 1e-12)) {
          const double a = s;
          const double b = s + rows.distance[i] + rows.distance[i + 1];
          for (std::size_t k = 0; k < run.sections.size(); ++k) {
            if (run.begin[k] <= b && run.begin[k] + run.sections[k].length_m >= a) {
              scale[k] *= kSlower;
              slowed = true;
            }
          }
        }
        s += rows.distance[i];
      }
      if (!slowed) break;
      if (attempt == kMaxSlowdowns) {
        throw Error("car timing: the steering rate could not be kept along a clothoid (internal)");
      }
    }
    // Stand and steer to the run's first angle (at least one row between runs: a stop).
    const double first = steerOf(rows.kappa.front(), car);
    const long standing = steeringRows(steer, first, l, r > 0 ? 1 : 0);
    for (long j = 1; j <= standing; ++j) push(0.0, 0.0, steer + (first - steer) * j / standing);
    for (std::size_t i = 0; i < rows.distance.size(); ++i) {
      push(run.direction * rows.distance[i] / dt, rows.kappa[i], steerOf(rows.kappa[i], car));
    }
    steer = steerOf(rows.kappa.back(), car);
  }
  traj.points.push_back({static_cast<double>(traj.points.size()) * dt, pose, {}, steer});
  return traj;
}

double carPathDuration(const std::vector<CarSection>& sections, const RobotDef& car,
                       const CarLimits& l) {
  checkLimits(l);
  long periods = 0;
  double steer = 0.0;
  const std::vector<Run> runs = runsOf(sections);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Run& run = runs[r];
    const Profile p = profileOf(run, car, l, std::vector<double>(run.sections.size(), 1.0));
    periods +=
        steeringRows(steer, steerOf(run.sections.front().kappa_begin, car), l, r > 0 ? 1 : 0);
    periods += periodsOf(p, l.period_s);
    steer = steerOf(run.sections.back().kappa_end, car);
  }
  return static_cast<double>(periods) * l.period_s;
}

}  // namespace parksim
