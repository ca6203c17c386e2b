#include "parksim/planner/steering/BalkcomMason.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {
namespace {

constexpr double kHalfBase = 0.0425;  // the study's robot

// Cost of the five-action path spin-drive-spin-drive-spin through the point (qx, qy): spin to
// face (or face away from) q, drive there, spin to face (or away from) the goal, drive there,
// spin to the goal heading. The best of the four direction choices.
double throughPoint(const Pose2& p, const Pose2& g, double qx, double qy) {
  const double d1 = std::hypot(qx - p.x, qy - p.y);
  const double d2 = std::hypot(g.x - qx, g.y - qy);
  const double b1 = std::atan2(qy - p.y, qx - p.x);
  const double b2 = std::atan2(g.y - qy, g.x - qx);
  double best = std::numeric_limits<double>::infinity();
  for (double f1 : {0.0, kPi}) {
    for (double f2 : {0.0, kPi}) {
      const double h1 = d1 > 0.0 ? b1 + f1 : p.theta;
      const double h2 = d2 > 0.0 ? b2 + f2 : h1;
      const double turn = std::abs(angleDiff(h1, p.theta)) + std::abs(angleDiff(h2, h1)) +
                          std::abs(angleDiff(g.theta, h2));
      best = std::min(best, d1 + d2 + kHalfBase * turn);
    }
  }
  return best;
}

// Brute force over the five-action family (which contains every family of up to four actions
// that starts or ends with a spin, and so every optimum): a 121 x 121 grid of middle points over
// a box holding every point a cheaper path could pass, then compass search from the 8 best, and
// fine searches along the start's and the goal's heading lines.
double bruteForce(const Pose2& p, const Pose2& g) {
  const double bound = throughPoint(p, g, p.x, p.y);
  const double x0 = std::min(p.x, g.x) - bound;
  const double y0 = std::min(p.y, g.y) - bound;
  const double x1 = std::max(p.x, g.x) + bound;
  const double y1 = std::max(p.y, g.y) + bound;
  constexpr int kN = 121;
  struct Sample {
    double cost, x, y;
  };
  std::vector<Sample> samples;
  for (int i = 0; i < kN; ++i) {
    for (int j = 0; j < kN; ++j) {
      const double x = x0 + (x1 - x0) * i / (kN - 1);
      const double y = y0 + (y1 - y0) * j / (kN - 1);
      samples.push_back({throughPoint(p, g, x, y), x, y});
    }
  }
  samples.push_back({throughPoint(p, g, p.x, p.y), p.x, p.y});
  samples.push_back({throughPoint(p, g, g.x, g.y), g.x, g.y});
  std::partial_sort(samples.begin(), samples.begin() + 8, samples.end(),
                    [](const Sample& a, const Sample& b) { return a.cost < b.cost; });
  double best = samples.front().cost;
  // Optima with a spin of zero lie on a kink of the cost (the middle point on the start's or
  // the goal's heading line), where compass steps stall: search those lines finely as well.
  for (const Pose2& line : {p, g}) {
    const double c = std::cos(line.theta);
    const double s = std::sin(line.theta);
    auto at = [&](double t) { return throughPoint(p, g, line.x + t * c, line.y + t * s); };
    constexpr int kLine = 4001;
    double best_t = 0.0;
    double best_c = at(0.0);
    for (int i = 0; i < kLine; ++i) {
      const double t = -bound + 2.0 * bound * i / (kLine - 1);
      if (const double v = at(t); v < best_c) {
        best_c = v;
        best_t = t;
      }
    }
    for (double step = 2.0 * bound / (kLine - 1); step > 1e-12; step *= 0.5) {
      for (const double t : {best_t - step, best_t + step}) {
        if (const double v = at(t); v < best_c) {
          best_c = v;
          best_t = t;
        }
      }
    }
    best = std::min(best, best_c);
  }
  for (int k = 0; k < 8; ++k) {
    Sample s = samples[k];
    for (double step = (x1 - x0) / (kN - 1); step > 1e-10; step *= 0.5) {
      bool moved = true;
      while (moved) {
        moved = false;
        for (const auto& [dx, dy] : {std::pair{1.0, 0.0},
                                     {-1.0, 0.0},
                                     {0.0, 1.0},
                                     {0.0, -1.0},
                                     {0.7071, 0.7071},
                                     {-0.7071, 0.7071},
                                     {0.7071, -0.7071},
                                     {-0.7071, -0.7071}}) {
          const double c = throughPoint(p, g, s.x + step * dx, s.y + step * dy);
          if (c < s.cost - 1e-15) {
            s = {c, s.x + step * dx, s.y + step * dy};
            moved = true;
          }
        }
      }
    }
    best = std::min(best, s.cost);
  }
  return best;
}

Pose2 randomPose(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> pos(-scale, scale), ang(-kPi, kPi);
  return {pos(rng), pos(rng), ang(rng)};
}

TEST(BalkcomMason, MatchesABruteForceOptimumOnRandomPosePairs) {
  std::mt19937_64 rng(18);
  int four_actions = 0;
  // Scales around the half wheel base, where turning and driving cost alike and the families
  // differ most, and larger ones.
  for (int i = 0; i < 120; ++i) {
    const double scale = i < 80 ? 0.05 : 0.5;
    const Pose2 from = randomPose(rng, scale);
    const Pose2 to = randomPose(rng, scale);
    const SpinDrivePath path = balkcomMasonPath(from, to, kHalfBase);
    const double brute = bruteForce(from, to);
    EXPECT_LE(path.cost_m, brute + 1e-9) << "pair " << i;
    EXPECT_GE(path.cost_m, brute - 1e-7) << "pair " << i;
    EXPECT_LE(path.actions.size(), 4u);
    if (path.actions.size() == 4) ++four_actions;
    const Pose2 end = endPose(from, path);
    EXPECT_NEAR(end.x, to.x, 1e-9) << "pair " << i;
    EXPECT_NEAR(end.y, to.y, 1e-9) << "pair " << i;
    EXPECT_NEAR(angleDiff(end.theta, to.theta), 0.0, 1e-9) << "pair " << i;
  }
  // The four-action families are needed: some pairs take them.
  EXPECT_GT(four_actions, 5);
}

TEST(BalkcomMason, KnownCases) {
  const double h = kHalfBase;
  // Straight ahead and straight back: drive only.
  EXPECT_NEAR(balkcomMasonCost({0, 0, 0}, {1, 0, 0}, h), 1.0, 1e-12);
  EXPECT_NEAR(balkcomMasonCost({0, 0, 0}, {-1, 0, 0}, h), 1.0, 1e-12);
  // Turning in place only.
  EXPECT_NEAR(balkcomMasonCost({0, 0, 0}, {0, 0, 1.0}, h), h, 1e-12);
  // Sideways by 1 m far from the wheel scale: turn a quarter, drive, turn back.
  EXPECT_NEAR(balkcomMasonCost({0, 0, 0}, {0, 1, 0}, h), 1.0 + h * kPi, 1e-12);
  // The cost alone is the path's cost; the bound never exceeds it.
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Pose2 a = randomPose(rng, 0.3);
    const Pose2 b = randomPose(rng, 0.3);
    EXPECT_NEAR(balkcomMasonCost(a, b, h), balkcomMasonPath(a, b, h).cost_m, 1e-9);
    EXPECT_LE(spinDriveLowerBound(a, b, h), balkcomMasonCost(a, b, h) + 1e-12);
  }
}

TEST(BalkcomMason, PiecesDriveThePathExactly) {
  const RobotDef robot;
  std::mt19937_64 rng(5);
  for (int i = 0; i < 100; ++i) {
    const Pose2 from = randomPose(rng, 0.2);
    const Pose2 to = randomPose(rng, 0.2);
    const SpinDrivePath path = balkcomMasonPath(from, to, 0.5 * robot.wheel_base_m);
    Pose2 p = from;
    double travel = 0.0;
    for (const PathPiece& piece : piecesOf(path, robot)) {
      const WheelSpeeds w{piece.direction.left_radps * piece.travel_rad,
                          piece.direction.right_radps * piece.travel_rad};
      p = integrateExact(p, toTwist(w, robot), 1.0);
      travel += piece.travel_rad;
    }
    EXPECT_NEAR(p.x, to.x, 1e-9);
    EXPECT_NEAR(p.y, to.y, 1e-9);
    EXPECT_NEAR(angleDiff(p.theta, to.theta), 0.0, 1e-9);
    // The faster wheel turns cost / r: the path's time at full speed.
    EXPECT_NEAR(travel, path.cost_m / robot.wheel_radius_m, 1e-9);
  }
}

TEST(BalkcomMason, RefusesANonPositiveHalfBase) {
  EXPECT_THROW(balkcomMasonPath({}, {1, 0, 0}, 0.0), Error);
}

}  // namespace
}  // namespace parksim
