// Circles and convex polygons in the collision adapter, against the independent exact
// reference of tests/support/ExactShapes.h (Minkowski differences and centre-to-outline
// distances, sharing no code with core's separating axes or with Bullet): the same random-pose
// and near-contact agreement checks the box tests make, and clearance. Counts over 100,000s of
// poses: the program (shape_agreement_tests) runs once, in the Release pass of scripts/test.sh.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/model/Geometry.h"
#include "tests/support/ExactShapes.h"
#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

using testing::exactSignedDistance;

#ifdef NDEBUG
constexpr int kSweepDivisor = 1;
constexpr int kDirectionStride = 1;
#else
constexpr int kSweepDivisor = 20;
constexpr int kDirectionStride = 3;
#endif

constexpr double kMargins[] = {0.0, 0.0005, 0.002};

std::vector<Eigen::Vector2d> regularPolygon(const Eigen::Vector2d& c, double r, int n,
                                            double phase) {
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2.0 * kPi * i / n;
    out.push_back(c + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return out;
}

// Bollards of several sizes, a triangle, a kerb corner, a pentagon island and a thin sliver.
Scenario shapesLot() {
  Scenario s;
  s.name = "shapes";
  s.obstacles = {
      Obstacle::makeCircle("bollard_small", ObstacleKind::kBollard, {{0.3, 0.3}, 0.01}, 0.1),
      Obstacle::makeCircle("bollard", ObstacleKind::kBollard, {{0.7, 0.35}, 0.025}, 0.1),
      Obstacle::makeCircle("pillar", ObstacleKind::kPillar, {{1.2, 0.9}, 0.08}, 0.3),
      Obstacle::makePolygon("triangle", ObstacleKind::kIsland,
                            {{0.9, 0.2}, {1.1, 0.25}, {0.95, 0.4}}, 0.05),
      Obstacle::makePolygon("kerb_corner", ObstacleKind::kCurb,
                            {{1.5, 0.0}, {1.7, 0.0}, {1.7, 0.2}}, 0.05),
      Obstacle::makePolygon("island", ObstacleKind::kIsland,
                            regularPolygon({0.5, 0.9}, 0.12, 5, 0.3), 0.05),
      Obstacle::makePolygon("sliver", ObstacleKind::kCurb,
                            {{1.4, 0.6}, {1.7, 0.62}, {1.7, 0.63}, {1.4, 0.61}}, 0.05),
  };
  return s;
}

double referenceSignedDistance(const Scenario& s, const Pose2& pose, double margin) {
  const OrientedBox fp = footprintAt(s.robot, pose, margin);
  double best = std::numeric_limits<double>::infinity();
  for (const Obstacle& o : s.obstacles) best = std::min(best, exactSignedDistance(fp, o));
  return best;
}

TEST(ShapeObstacles, RandomPosesAgreeWithTheIndependentExactReference) {
  const Scenario s = shapesLot();
  const BulletCollisionWorld world(s);
  std::mt19937_64 rng(20261130);
  std::uniform_real_distribution<double> x(-0.1, 1.9);
  std::uniform_real_distribution<double> y(-0.1, 1.3);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  const int count = 60000 / kSweepDivisor;
  for (const double margin : kMargins) {
    int colliding = 0;
    int disagreements = 0;
    for (int k = 0; k < count; ++k) {
      const Pose2 pose{x(rng), y(rng), heading(rng)};
      const double d = referenceSignedDistance(s, pose, margin);
      const bool expected_free = d >= 0.0;
      colliding += expected_free ? 0 : 1;
      if (world.isFree(pose, margin) != expected_free && ++disagreements <= 5) {
        ADD_FAILURE() << "pose (" << pose.x << ", " << pose.y << ", " << pose.theta << ") margin "
                      << margin << ": reference distance " << d;
      }
    }
    EXPECT_EQ(disagreements, 0);
    EXPECT_GT(colliding, count / 50) << "margin " << margin;
  }
  EXPECT_GT(world.stats().shape_tests, 0u);
}

// Pose with the given heading on a ray from the obstacle's centre where the reference signed
// distance crosses `target` (bisection; the distance grows along the ray once outside).
Pose2 poseAtDistance(const RobotDef& robot, const Obstacle& o, double heading, double direction,
                     double margin, double target) {
  const auto at = [&](double t) {
    return Pose2{o.box.center.x() + t * std::cos(direction),
                 o.box.center.y() + t * std::sin(direction), heading};
  };
  const auto f = [&](double t) {
    return exactSignedDistance(footprintAt(robot, at(t), margin), o) - target;
  };
  double lo = 0.0;
  double hi = 0.5;
  EXPECT_LT(f(lo), 0.0);
  while (f(hi) <= 0.0) hi *= 2.0;
  while (hi - lo > 1e-14) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) <= 0.0 ? lo : hi) = mid;
  }
  return at(target > 0.0 ? hi : lo);
}

TEST(ShapeObstacles, NearContactPosesAreClassifiedCorrectly) {
  const Scenario lot = shapesLot();
  const double headings_deg[] = {0, 90, -90, 180, 30, 45, -12.5, 123.4};
  int cases = 0;
  int failures = 0;
  for (const Obstacle& obstacle : lot.obstacles) {
    Scenario single;
    single.obstacles = {obstacle};
    const BulletCollisionWorld world(single);
    for (const double heading_deg : headings_deg) {
      for (int d = 0; d < 24; d += kDirectionStride) {
        for (const double margin : kMargins) {
          for (const double delta : {1e-5, 1e-4}) {
            for (const double target : {delta, -delta}) {
              const Pose2 pose = poseAtDistance(single.robot, obstacle, degToRad(heading_deg),
                                                degToRad(15.0 * d), margin, target);
              ++cases;
              if (world.isFree(pose, margin) != (target > 0.0) && ++failures <= 10) {
                ADD_FAILURE() << obstacle.name << " heading " << heading_deg << " approach "
                              << 15 * d << " margin " << margin << " target " << target;
              }
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(failures, 0) << "of " << cases;
  EXPECT_EQ(cases, 7 * 8 * (24 / kDirectionStride) * 3 * 2 * 2);
}

TEST(ShapeObstacles, ClearanceMatchesTheIndependentExactDistance) {
  const Scenario s = shapesLot();
  const BulletCollisionWorld world(s);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-0.1, 1.9);
  std::uniform_real_distribution<double> y(-0.1, 1.3);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  for (int k = 0; k < 20000 / kSweepDivisor; ++k) {
    const Pose2 pose{x(rng), y(rng), heading(rng)};
    const double expected = std::max(0.0, referenceSignedDistance(s, pose, 0.0));
    ASSERT_NEAR(world.clearance(pose), expected, 1e-9)
        << "pose (" << pose.x << ", " << pose.y << ", " << pose.theta << ")";
  }
}

TEST(ShapeObstacles, TouchingACircleOrAPolygonEdgeIsFree) {
  // Dyadic numbers: the touching contacts are exact in double.
  Scenario s;
  s.robot.length_m = 0.125;
  s.robot.width_m = 0.0625;
  s.robot.front_overhang_m = 0.03125;
  s.obstacles = {Obstacle::makeCircle("c", ObstacleKind::kBollard, {{0.5, 0.5}, 0.0625}, 0.1),
                 Obstacle::makePolygon("p", ObstacleKind::kIsland,
                                       {{1.0, 0.25}, {1.25, 0.25}, {1.0, 0.5}}, 0.1)};
  const BulletCollisionWorld world(s);
  const double step = std::ldexp(1.0, -20);
  // Front edge (x = ref + 1/32) on the circle's west point x = 0.4375.
  const Pose2 on_circle{0.4375 - 0.03125, 0.5, 0.0};
  EXPECT_TRUE(world.isFree(on_circle));
  EXPECT_FALSE(world.isFree({on_circle.x + step, 0.5, 0.0}));
  // Facing east, front edge at x = ref + 1/32 = 1.0: touching the triangle's west face.
  const Pose2 face{1.0 - 0.03125, 0.375, 0.0};
  EXPECT_TRUE(world.isFree(face));
  EXPECT_FALSE(world.isFree({face.x + step, face.y, 0.0}));
  EXPECT_TRUE(world.isFree({face.x - step, face.y, 0.0}, step));
  EXPECT_FALSE(world.isFree({face.x - step, face.y, 0.0}, 2 * step));
}

TEST(ShapeObstacles, ObstaclesBelowTheGroundClearanceAreNotObstacles) {
  Scenario s;
  s.obstacles = {
      Obstacle::makeBox("painted", ObstacleKind::kCurb, testing::cornerBox(0.4, 0.0, 0.02, 1),
                        0.001),
      Obstacle::makeCircle("low_disc", ObstacleKind::kBollard, {{1.0, 0.5}, 0.05}, 0.002),
      Obstacle::makeCircle("bollard", ObstacleKind::kBollard, {{1.5, 0.5}, 0.05}, 0.0021)};
  const BulletCollisionWorld world(s);
  EXPECT_EQ(world.obstacleCount(), 1u);
  EXPECT_TRUE(world.isFree({0.41, 0.5, 0.0}));
  EXPECT_TRUE(world.isFree({1.0, 0.5, 0.0}));
  EXPECT_FALSE(world.isFree({1.5, 0.5, 0.0}));
  s.robot.ground_clearance_m = 0.0;  // no clearance: everything blocks
  EXPECT_EQ(BulletCollisionWorld(s).obstacleCount(), 3u);
}

}  // namespace
}  // namespace parksim
