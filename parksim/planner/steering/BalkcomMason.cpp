#include "parksim/planner/steering/BalkcomMason.h"

#include <cmath>
#include <limits>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

namespace {

// Actions shorter than this are left out, m or rad.
constexpr double kTinyAction = 1e-12;
// Drive headings this close to parallel with the final straight make no four-action path.
constexpr double kMinSine = 1e-9;
// A later candidate replaces the best only when cheaper by more than this, m.
constexpr double kCostTie = 1e-12;

void add(std::vector<SpinDriveAction>& actions, bool spin, double amount) {
  if (std::abs(amount) > kTinyAction) actions.push_back({spin, amount});
}

double costOf(const std::vector<SpinDriveAction>& actions, double h) {
  double c = 0.0;
  for (const SpinDriveAction& a : actions)
    c += a.spin ? h * std::abs(a.amount) : std::abs(a.amount);
  return c;
}

// A spin-drive-spin-drive path: turn, drive, turn, drive (any of them may be zero).
struct Quad {
  double spin1 = 0.0;
  double drive1 = 0.0;
  double spin2 = 0.0;
  double drive2 = 0.0;

  double cost(double h) const {
    return h * (std::abs(spin1) + std::abs(spin2)) + std::abs(drive1) + std::abs(drive2);
  }
};

// Calls offer(quad) for the spin-drive-spin-drive paths from `p` to `q` that can be optimal
// (they contain the shorter ones): the direct spin-drive-spin both ways, the drive-spin-drive
// along the start heading, and the stationary points of the cost in the drive heading psi
// measured from the final heading (file comment).
template <class Offer>
void forEachCandidate(const Pose2& p, const Pose2& q, double h, Offer&& offer) {
  const double wx = q.x - p.x;
  const double wy = q.y - p.y;
  const double dist = std::hypot(wx, wy);
  if (dist <= kTinyAction) {
    offer(Quad{angleDiff(q.theta, p.theta), 0.0, 0.0, 0.0});
    return;
  }
  const double bearing = std::atan2(wy, wx);
  offer(Quad{angleDiff(bearing, p.theta), dist, angleDiff(q.theta, bearing), 0.0});
  offer(Quad{angleDiff(bearing + kPi, p.theta), -dist, angleDiff(q.theta, bearing + kPi), 0.0});
  // The displacement in the final heading's frame: along (a) and to the left of it (b).
  const double c1 = std::cos(q.theta);
  const double s1 = std::sin(q.theta);
  const double a = wx * c1 + wy * s1;
  const double b = -wx * s1 + wy * c1;
  // Drive heading beta = theta1 - psi to Q, turn to theta1, drive s to q: Q = p + d e(beta)
  // with d = -b / sin(psi), s = a + b cot(psi).
  auto offerPsi = [&](double psi) {
    const double sn = std::sin(psi);
    if (std::abs(sn) < kMinSine) return;
    const double beta = q.theta - psi;
    offer(Quad{angleDiff(beta, p.theta), -b / sn, angleDiff(q.theta, beta),
               a + b * std::cos(psi) / sn});
  };
  offerPsi(angleDiff(q.theta, p.theta));  // no first spin: drive-spin-drive
  // Where the two spins turn opposite ways, d cost / d psi = 0 reads
  // sigma1 |b| cos(psi) + sigma2 b = k sin^2(psi), k = +-2h, sigma1 = sign(sin psi),
  // sigma2 = sign(s): a quadratic in x = cos(psi), k x^2 + sigma1 |b| x + sigma2 b - k = 0.
  for (const double k : {2.0 * h, -2.0 * h}) {
    for (const double sigma1 : {1.0, -1.0}) {
      for (const double sigma2 : {1.0, -1.0}) {
        const double qb = sigma1 * std::abs(b);
        const double qc = sigma2 * b - k;
        const double disc = qb * qb - 4.0 * k * qc;
        if (disc < 0.0) continue;
        const double root = std::sqrt(disc);
        for (const double x : {(-qb + root) / (2.0 * k), (-qb - root) / (2.0 * k)}) {
          if (!(x >= -1.0 && x <= 1.0)) continue;
          offerPsi(sigma1 * std::acos(x));
        }
      }
    }
  }
}

// The cheapest candidate of forEachCandidate; ties keep the first.
Quad cheapest(const Pose2& p, const Pose2& q, double h, double* cost) {
  Quad best;
  double best_cost = std::numeric_limits<double>::infinity();
  forEachCandidate(p, q, h, [&](const Quad& c) {
    const double v = c.cost(h);
    if (v < best_cost - kCostTie) {
      best = c;
      best_cost = v;
    }
  });
  *cost = best_cost;
  return best;
}

}  // namespace

SpinDrivePath balkcomMasonPath(const Pose2& from, const Pose2& to, double half_base_m) {
  if (!(half_base_m > 0.0)) throw Error("balkcom-mason: half wheel base must be positive");
  double forward_cost = 0.0;
  double backward_cost = 0.0;
  const Quad f = cheapest(from, to, half_base_m, &forward_cost);
  // Drive-spin-drive-spin is spin-drive-spin-drive from `to` back to `from`, driven backwards
  // in time: the actions in reverse order, each negated.
  const Quad b = cheapest(to, from, half_base_m, &backward_cost);
  SpinDrivePath path;
  if (backward_cost < forward_cost - kCostTie) {
    add(path.actions, false, -b.drive2);
    add(path.actions, true, -b.spin2);
    add(path.actions, false, -b.drive1);
    add(path.actions, true, -b.spin1);
  } else {
    add(path.actions, true, f.spin1);
    add(path.actions, false, f.drive1);
    add(path.actions, true, f.spin2);
    add(path.actions, false, f.drive2);
  }
  path.cost_m = costOf(path.actions, half_base_m);
  return path;
}

double balkcomMasonCost(const Pose2& from, const Pose2& to, double half_base_m) {
  if (!(half_base_m > 0.0)) throw Error("balkcom-mason: half wheel base must be positive");
  double forward_cost = 0.0;
  double backward_cost = 0.0;
  cheapest(from, to, half_base_m, &forward_cost);
  cheapest(to, from, half_base_m, &backward_cost);
  return std::min(forward_cost, backward_cost);
}

double spinDriveLowerBound(const Pose2& from, const Pose2& to, double half_base_m) {
  return positionDistance(from, to) + half_base_m * headingDistance(from, to);
}

Pose2 endPose(const Pose2& from, const SpinDrivePath& path) {
  Pose2 p = from;
  for (const SpinDriveAction& a : path.actions) {
    if (a.spin) {
      p.theta = wrapAngle(p.theta + a.amount);
    } else {
      p.x += a.amount * std::cos(p.theta);
      p.y += a.amount * std::sin(p.theta);
    }
  }
  return p;
}

std::vector<PathPiece> piecesOf(const SpinDrivePath& path, const RobotDef& robot) {
  std::vector<PathPiece> pieces;
  for (const SpinDriveAction& a : path.actions) {
    const Twist t = a.spin ? Twist{0.0, a.amount} : Twist{a.amount, 0.0};
    appendPiece(pieces, pieceOf(toWheelSpeeds(t, robot), 1.0));
  }
  return pieces;
}

}  // namespace parksim
