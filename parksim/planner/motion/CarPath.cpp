#include "parksim/planner/motion/CarPath.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

namespace {

// Pieces shorter than this are rounding, m; curvatures closer than this are one, 1/m.
constexpr double kTinyLength_m = 1e-12;
constexpr double kSameCurvature = 1e-9;
// The heading's residual is weighed as this many metres per radian in correctedEnd.
constexpr double kHeadingScale_m = 1.0;
constexpr int kMaxNewtonSteps = 30;
constexpr double kConverged = 1e-9;

// Drives `length` of a section whose curvature is `kappa` there on average.
Pose2 driveArc(const Pose2& from, int direction, double length, double kappa) {
  return integrateExact(from, {direction * length, direction * length * kappa}, 1.0);
}

// Drives the whole of `s` from `from` (clothoids in steps of at most step_m).
Pose2 driveSection(const Pose2& from, const CarSection& s, double step_m) {
  if (s.constantCurvature()) return driveArc(from, s.direction, s.length_m, s.kappa_begin);
  const int n = std::max(1, static_cast<int>(std::ceil(s.length_m / step_m)));
  Pose2 pose = from;
  for (int k = 0; k < n; ++k) {
    // The mean curvature of the k-th step of a linear curvature is its middle's.
    const double mid = (k + 0.5) / n;
    pose = driveArc(pose, s.direction, s.length_m / n,
                    s.kappa_begin + mid * (s.kappa_end - s.kappa_begin));
  }
  return pose;
}

}  // namespace

std::vector<CarSection> carSections(const std::vector<PathPiece>& pieces, const RobotDef& car) {
  std::vector<CarSection> out;
  const double kappa_max = car.maxCurvature();
  for (const PathPiece& p : pieces) {
    if (!(p.travel_rad > 0.0)) continue;
    const Twist m = toTwist(
        {p.direction.left_radps * p.travel_rad, p.direction.right_radps * p.travel_rad}, car);
    const double length = std::abs(m.v_mps);
    if (!(length > kTinyLength_m)) {
      if (std::abs(m.omega_radps) > kTinyLength_m) {
        throw Error("car path: a piece turns in place, which a car cannot");
      }
      continue;
    }
    const double kappa = m.omega_radps / m.v_mps;
    if (std::abs(kappa) > kappa_max * (1.0 + 1e-6)) {
      throw Error("car path: a piece's curvature exceeds the car's tan(max_steer) / axle");
    }
    const double k = std::clamp(kappa, -kappa_max, kappa_max);
    const int direction = m.v_mps > 0.0 ? 1 : -1;
    if (!out.empty() && out.back().direction == direction &&
        std::abs(out.back().kappa_end - k) <= kSameCurvature) {
      out.back().length_m += length;
      continue;
    }
    out.push_back({direction, length, k, k});
  }
  return out;
}

bool stopsBetween(const CarSection& a, const CarSection& b) {
  return a.direction != b.direction || a.kappa_end != b.kappa_begin;
}

Pose2 endOf(const Pose2& start, const std::vector<CarSection>& sections, double step_m) {
  Pose2 pose = start;
  for (const CarSection& s : sections) pose = driveSection(pose, s, step_m);
  return pose;
}

std::vector<CarSection> transitions(
    const std::vector<CarSection>& sections,
    const std::function<double(std::size_t junction, double kappa_before, double kappa_after)>&
        half_length,
    std::vector<long>* junction_of) {
  const std::size_t n = sections.size();
  // h[i]: the half-length of the clothoid between sections i and i + 1.
  std::vector<double> h(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const CarSection& a = sections[i];
    const CarSection& b = sections[i + 1];
    if (a.direction != b.direction || a.kappa_end == b.kappa_begin) continue;
    if (!a.constantCurvature() || !b.constantCurvature()) continue;
    const double wanted = half_length(i, a.kappa_end, b.kappa_begin);
    h[i] = std::max(0.0, std::min({wanted, 0.5 * a.length_m, 0.5 * b.length_m}));
  }
  std::vector<CarSection> out;
  if (junction_of) junction_of->clear();
  for (std::size_t i = 0; i < n; ++i) {
    CarSection s = sections[i];
    s.length_m -= (i > 0 ? h[i - 1] : 0.0) + h[i];
    if (s.length_m > kTinyLength_m) {
      out.push_back(s);
      if (junction_of) junction_of->push_back(-1);
    }
    if (h[i] > 0.0) {
      out.push_back({s.direction, 2.0 * h[i], sections[i].kappa_end, sections[i + 1].kappa_begin});
      if (junction_of) junction_of->push_back(static_cast<long>(i));
    }
  }
  return out;
}

std::optional<std::vector<CarSection>> correctedEnd(const Pose2& start,
                                                    std::vector<CarSection> sections,
                                                    const Pose2& target, double min_length_m) {
  std::vector<std::size_t> free;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    if (sections[i].constantCurvature() && sections[i].length_m > min_length_m) free.push_back(i);
  }
  for (int step = 0; step <= kMaxNewtonSteps; ++step) {
    // The poses where sections end, and the residual at the path's end.
    std::vector<Pose2> ends;
    Pose2 pose = start;
    for (const CarSection& s : sections) {
      pose = driveSection(pose, s, 0.02);
      ends.push_back(pose);
    }
    const Eigen::Vector3d r(target.x - pose.x, target.y - pose.y,
                            kHeadingScale_m * angleDiff(target.theta, pose.theta));
    if (std::hypot(r.x(), r.y()) < kConverged && std::abs(r.z()) < kConverged) return sections;
    if (step == kMaxNewtonSteps || free.empty()) break;
    // Lengthening section j by e moves what follows it rigidly: along its end's tangent by e and
    // turned by its curvature times e about its end.
    Eigen::Matrix3Xd jac(3, static_cast<Eigen::Index>(free.size()));
    Eigen::VectorXd weight(static_cast<Eigen::Index>(free.size()));
    for (std::size_t c = 0; c < free.size(); ++c) {
      const CarSection& s = sections[free[c]];
      const Pose2& e = ends[free[c]];
      const double turn = s.direction * s.kappa_end;
      jac(0, c) = s.direction * std::cos(e.theta) - turn * (pose.y - e.y);
      jac(1, c) = s.direction * std::sin(e.theta) + turn * (pose.x - e.x);
      jac(2, c) = kHeadingScale_m * turn;
      weight(c) = s.length_m;
    }
    const Eigen::Matrix3d m =
        jac * weight.asDiagonal() * jac.transpose() + 1e-12 * Eigen::Matrix3d::Identity();
    const Eigen::VectorXd delta = weight.asDiagonal() * jac.transpose() * m.ldlt().solve(r);
    // As much of the step as keeps every section long enough.
    double alpha = 1.0;
    for (std::size_t c = 0; c < free.size(); ++c) {
      const double l = sections[free[c]].length_m;
      if (l + delta(c) < min_length_m) alpha = std::min(alpha, (l - min_length_m) / -delta(c));
    }
    if (!(alpha > 1e-6)) break;
    for (std::size_t c = 0; c < free.size(); ++c) sections[free[c]].length_m += alpha * delta(c);
  }
  return std::nullopt;
}

}  // namespace parksim
