#include "parksim/collision/BulletCollisionWorld.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

using testing::cornerBox;
using testing::makeObstacle;
using testing::studyLot;

// Optimised builds run every case; unoptimised (sanitised Debug) builds run a fraction of the
// random sweeps and every third approach direction, so that they finish within seconds.
#ifdef NDEBUG
constexpr int kSweepDivisor = 1;
constexpr int kDirectionStride = 1;
#else
constexpr int kSweepDivisor = 20;
constexpr int kDirectionStride = 3;
#endif

constexpr double kMargins[] = {0.0, 0.0005, 0.002};

std::string describe(const Pose2& pose, double margin) {
  std::ostringstream out;
  out << std::setprecision(17) << "pose (" << pose.x << ", " << pose.y << ", " << pose.theta
      << ") margin " << margin;
  return out.str();
}

Pose2 randomLotPose(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> x(-0.1, 1.9);
  std::uniform_real_distribution<double> y(-0.1, 1.3);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  return {x(rng), y(rng), heading(rng)};
}

// The exact reference: separating axes in double against every obstacle.
std::vector<std::string> satOverlapping(const Scenario& s, const Pose2& pose, double margin) {
  const OrientedBox footprint = footprintAt(s.robot, pose, margin);
  std::vector<std::string> names;
  for (const Obstacle& o : s.obstacles) {
    if (boxesOverlap(footprint, o.box)) names.push_back(o.name);
  }
  return names;
}

double satMinSeparation(const Scenario& s, const Pose2& pose, double margin) {
  const OrientedBox footprint = footprintAt(s.robot, pose, margin);
  double best = std::numeric_limits<double>::infinity();
  for (const Obstacle& o : s.obstacles) {
    best = std::min(best, std::abs(separationAlongAxes(footprint, o.box)));
  }
  return best;
}

// Compares isFree with the exact reference on `count` random poses per margin.
void expectAgreementOnRandomPoses(const Scenario& scenario, int count, std::uint64_t seed) {
  const BulletCollisionWorld world(scenario);
  std::mt19937_64 rng(seed);
  for (const double margin : kMargins) {
    int disagreements = 0;
    int colliding = 0;
    for (int k = 0; k < count; ++k) {
      const Pose2 pose = randomLotPose(rng);
      const bool expected_free = satOverlapping(scenario, pose, margin).empty();
      colliding += expected_free ? 0 : 1;
      if (world.isFree(pose, margin) != expected_free) {
        ++disagreements;
        if (disagreements <= 5) {
          ADD_FAILURE() << describe(pose, margin) << ": exact says "
                        << (expected_free ? "free" : "colliding") << ", smallest |separation| "
                        << satMinSeparation(scenario, pose, margin) << " m";
        }
      }
    }
    EXPECT_EQ(disagreements, 0) << "margin " << margin << ", " << count << " poses";
    // A sweep that is almost all free (or all colliding) would prove little.
    EXPECT_GT(colliding, count / 10) << "margin " << margin;
    EXPECT_LT(colliding, count * 9 / 10) << "margin " << margin;
  }
}

// Distance between two convex polygons computed independently of the library: the distance
// from the origin to their Minkowski difference, the convex hull of all corner differences.
double minkowskiDistance(const OrientedBox& a, const OrientedBox& b) {
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector2d& p : a.corners()) {
    for (const Eigen::Vector2d& q : b.corners()) points.push_back(p - q);
  }
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
  });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return (u - o).x() * (v - o).y() - (u - o).y() * (v - o).x();
  };
  // Andrew's monotone chain, counter-clockwise.
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);

  const Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  bool inside = true;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& p = hull[i];
    const Eigen::Vector2d& q = hull[(i + 1) % hull.size()];
    if (cross(p, q, origin) < 0) inside = false;
    const Eigen::Vector2d pq = q - p;
    const double t = std::clamp(-p.dot(pq) / pq.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p + t * pq).norm());
  }
  return inside ? 0.0 : best;
}

double referenceClearance(const Scenario& s, const Pose2& pose) {
  const OrientedBox footprint = footprintAt(s.robot, pose);
  double best = std::numeric_limits<double>::infinity();
  for (const Obstacle& o : s.obstacles) best = std::min(best, minkowskiDistance(footprint, o.box));
  return best;
}

OrientedBox rotatedBox(double cx, double cy, double half_x, double half_y, double yaw_deg) {
  OrientedBox box;
  box.center = {cx, cy};
  box.half_extents = {half_x, half_y};
  box.yaw = degToRad(yaw_deg);
  return box;
}

Scenario rotatedObstacles() {
  Scenario s;
  s.name = "rotated";
  const auto box = [](const char* name, const OrientedBox& b) {
    return makeObstacle(name, ObstacleKind::kBox, b, 0.1);
  };
  s.obstacles = {
      box("rot30_bar", rotatedBox(0.4, 0.4, 0.1, 0.03, 30)),
      box("rot30_robot", rotatedBox(1.0, 0.8, 0.0425, 0.04, 30)),
      box("rot30_long", rotatedBox(1.5, 0.3, 0.3, 0.05, 30)),
      box("rot30_square", rotatedBox(0.3, 1.0, 0.06, 0.06, 30)),
      box("rot-60", rotatedBox(0.8, 0.2, 0.05, 0.12, -60)),
      box("rot137", rotatedBox(1.3, 1.05, 0.08, 0.02, 137)),
  };
  return s;
}

Scenario singleObstacle(const Obstacle& obstacle) {
  Scenario s;
  s.name = "single";
  s.obstacles = {obstacle};
  return s;
}

// Pose with the given heading, its reference point on the ray from the box centre in
// direction `direction`, where the exact separation of the footprint from the box crosses
// `target`. Along the ray the separation is convex and negative at the start, so it crosses
// each level above its start value once; bisection keeps f(lo) <= 0 < f(hi) and returns the
// end on the far side of touching, so the pose is at least |target| from touching.
Pose2 poseAtSeparation(const RobotDef& robot, const OrientedBox& box, double heading,
                       double direction, double margin, double target) {
  const auto at = [&](double t) {
    return Pose2{box.center.x() + t * std::cos(direction), box.center.y() + t * std::sin(direction),
                 heading};
  };
  const auto f = [&](double t) {
    return separationAlongAxes(footprintAt(robot, at(t), margin), box) - target;
  };
  double lo = 0.0;
  double hi = 0.5;
  EXPECT_LT(f(lo), 0.0) << "the ray must start inside the box";
  while (f(hi) <= 0.0) hi *= 2.0;
  // 1e-14 m is far below the 1e-5 m being tested and saves a dozen halvings.
  while (hi - lo > 1e-14) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) <= 0.0 ? lo : hi) = mid;
  }
  return at(target > 0.0 ? hi : lo);
}

// (a) The study's lot: random poses over and around it, every heading, three margins.
TEST(BulletCollisionWorld, RandomLotPosesAgreeWithExactSeparatingAxes) {
  expectAgreementOnRandomPoses(studyLot(), 200000 / kSweepDivisor, 20240611);
}

// (c) Obstacles at 30 degrees and other yaws.
TEST(BulletCollisionWorld, RandomPosesAmongRotatedObstaclesAgreeWithExactSeparatingAxes) {
  expectAgreementOnRandomPoses(rotatedObstacles(), 50000 / kSweepDivisor, 7);
}

// (b) Footprints 1e-5 m and 1e-4 m from touching, on either side, approaching every
// obstacle of the lot and the rotated ones from 24 directions at 8 headings.
TEST(BulletCollisionWorld, NearContactPosesAreClassifiedCorrectly) {
  std::vector<Obstacle> obstacles = studyLot().obstacles;
  for (const Obstacle& o : rotatedObstacles().obstacles) obstacles.push_back(o);
  const double headings_deg[] = {0, 90, -90, 180, 30, 45, -12.5, 123.4};
  const RobotDef robot;
  int cases = 0;
  int failures = 0;
  for (const Obstacle& obstacle : obstacles) {
    const BulletCollisionWorld world(singleObstacle(obstacle));
    for (const double heading_deg : headings_deg) {
      for (int d = 0; d < 24; d += kDirectionStride) {
        const double direction = degToRad(15.0 * d);
        for (const double margin : kMargins) {
          for (const double delta : {1e-5, 1e-4}) {
            for (const double target : {delta, -delta}) {
              const Pose2 pose = poseAtSeparation(robot, obstacle.box, degToRad(heading_deg),
                                                  direction, margin, target);
              const double separation =
                  separationAlongAxes(footprintAt(robot, pose, margin), obstacle.box);
              ASSERT_NEAR(separation, target, 1e-9) << obstacle.name;
              ++cases;
              if (world.isFree(pose, margin) != (target > 0.0)) {
                if (++failures <= 10) {
                  ADD_FAILURE() << obstacle.name << " " << describe(pose, margin) << ": separation "
                                << separation << " m, heading " << heading_deg << " deg, approach "
                                << 15 * d << " deg";
                }
              }
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(failures, 0) << "of " << cases << " near-contact cases";
  EXPECT_EQ(cases, 17 * 8 * (24 / kDirectionStride) * 3 * 2 * 2);
}

// Boxes that only touch do not overlap. Dyadic sizes make every coordinate exact in float
// and double alike, so this is a real touch for Bullet as well.
TEST(BulletCollisionWorld, ExactTouchingIsFreeAndTheSmallestOverlapIsNot) {
  Scenario s;
  s.robot.length_m = 0.125;
  s.robot.width_m = 0.0625;
  s.robot.front_overhang_m = 0.03125;
  s.robot.height_m = 0.0625;
  s.obstacles = {
      makeObstacle("block", ObstacleKind::kBox, cornerBox(0.5, 0.25, 0.125, 0.25), 0.125)};
  const BulletCollisionWorld world(s);

  // Front edge on the block's west face (x = 0.5).
  const Pose2 face{0.46875, 0.375, 0.0};
  EXPECT_TRUE(satOverlapping(s, face, 0.0).empty());
  EXPECT_TRUE(world.isFree(face));
  EXPECT_EQ(world.clearance(face), 0.0);
  const double step = std::ldexp(1.0, -20);  // about 1e-6 m
  EXPECT_FALSE(world.isFree({face.x + step, face.y, 0.0}));
  EXPECT_TRUE(world.isFree({face.x - step, face.y, 0.0}));
  // A margin of one step closes the gap exactly; two steps overlap.
  EXPECT_TRUE(world.isFree({face.x - step, face.y, 0.0}, step));
  EXPECT_FALSE(world.isFree({face.x - step, face.y, 0.0}, 2 * step));

  // Footprint's north-east corner on the block's south-west corner (0.5, 0.25).
  const Pose2 corner{0.46875, 0.25 - 0.03125, 0.0};
  EXPECT_TRUE(world.isFree(corner));
  EXPECT_FALSE(world.isFree({corner.x + step, corner.y + step, 0.0}));
  // Sliding along the face while touching stays free.
  EXPECT_TRUE(world.isFree({face.x, 0.3, 0.0}));
}

// (d) clearance against the Minkowski-difference distance, over the lot and far from it.
TEST(BulletCollisionWorld, ClearanceMatchesAnIndependentExactDistance) {
  const Scenario lot = studyLot();
  const BulletCollisionWorld world(lot);
  std::mt19937_64 rng(99);
  const int count = 20000 / kSweepDivisor;
  int positive = 0;
  double worst = 0.0;
  for (int k = 0; k < count; ++k) {
    const Pose2 pose = randomLotPose(rng);
    const double expected = referenceClearance(lot, pose);
    const double got = world.clearance(pose);
    worst = std::max(worst, std::abs(got - expected));
    ASSERT_NEAR(got, expected, 1e-9) << describe(pose, 0.0);
    EXPECT_EQ(got == 0.0, !satOverlapping(lot, pose, 0.0).empty()) << describe(pose, 0.0);
    positive += got > 0.0 ? 1 : 0;
  }
  EXPECT_GT(positive, count / 2);
  EXPECT_LT(worst, 1e-12);

  // Far outside the lot the search radius must grow several times.
  std::uniform_real_distribution<double> far_x(-20.0, 20.0);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  for (int k = 0; k < 10000 / kSweepDivisor; ++k) {
    const Pose2 pose{far_x(rng), far_x(rng), heading(rng)};
    ASSERT_NEAR(world.clearance(pose), referenceClearance(lot, pose), 1e-9) << describe(pose, 0);
  }
}

TEST(BulletCollisionWorld, ClearanceKnownValues) {
  const Scenario lot = studyLot();
  const BulletCollisionWorld world(lot);
  // Facing +x, front edge at x = 0.45, 50 mm short of wall_2.
  EXPECT_NEAR(world.clearance({0.44, 0.2, 0.0}), 0.05, 1e-12);
  // Head-in goal: 72.5 mm to robot_5 (x <= 1.385) and 57.5 mm to robot_6 (x >= 1.6).
  EXPECT_NEAR(world.clearance({1.5, 0.04, degToRad(-90)}), 0.0575, 1e-12);
  EXPECT_EQ(world.clearance({1.2, 0.65, 0.0}), 0.0);  // inside the island

  const BulletCollisionWorld empty(Scenario{});
  EXPECT_EQ(empty.clearance({0.0, 0.0, 0.0}), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(empty.isFree({0.0, 0.0, 0.0}, 1.0));
  EXPECT_TRUE(empty.overlapping({0.0, 0.0, 0.0}).empty());
}

// (e) Names, in scenario order.
TEST(BulletCollisionWorld, OverlappingNamesTheObstaclesHit) {
  const Scenario lot = studyLot();
  const BulletCollisionWorld world(lot);
  using Names = std::vector<std::string>;
  EXPECT_EQ(world.overlapping({1.2, 0.65, 0.0}), Names{"island_7"});
  EXPECT_EQ(world.overlapping(lot.start), Names{});
  // Facing +y between wall_2 (x <= 0.6) and robot_3 (x >= 0.7): the footprint spans
  // x 0.6075..0.6925, so a 10 mm margin reaches both by 2.5 mm.
  const Pose2 between{0.65, 0.05, degToRad(90)};
  EXPECT_EQ(world.overlapping(between), Names{});
  EXPECT_EQ(world.overlapping(between, 0.001), Names{});
  EXPECT_EQ(world.overlapping(between, 0.01), (Names{"wall_2", "robot_3"}));
  EXPECT_FALSE(world.isFree(between, 0.01));
  // A 0.5 m margin from the island's middle spans y 0.1075..1.1925 and x 0.63..1.71: the
  // whole north row, none of the south row (y <= 0.08) and neither wall (x <= 0.6).
  EXPECT_EQ(world.overlapping({1.2, 0.65, 0.0}, 0.5),
            (Names{"island_7", "robot_8", "robot_9", "robot_10", "robot_11"}));
}

TEST(BulletCollisionWorld, OverlappingAgreesWithExactSeparatingAxesOnRandomPoses) {
  for (const Scenario& scenario : {studyLot(), rotatedObstacles()}) {
    const BulletCollisionWorld world(scenario);
    std::mt19937_64 rng(5);
    for (int k = 0; k < 20000 / kSweepDivisor; ++k) {
      const Pose2 pose = randomLotPose(rng);
      const double margin = kMargins[k % 3];
      ASSERT_EQ(world.overlapping(pose, margin), satOverlapping(scenario, pose, margin))
          << scenario.name << " " << describe(pose, margin);
    }
  }
}

TEST(BulletCollisionWorld, StatsCountQueriesAndReset) {
  BulletCollisionWorld world(studyLot());
  EXPECT_EQ(world.obstacleCount(), 11u);
  world.isFree({0.1, 0.1, 0.0});
  world.isFree({1.2, 0.65, 0.0});
  world.isFree({1.2, 0.65, 0.0}, 0.002);
  world.overlapping({1.2, 0.65, 0.0});
  world.clearance({0.1, 0.1, 0.0});
  world.clearance({0.44, 0.2, 0.0});
  BulletCollisionWorld::Stats stats = world.stats();
  EXPECT_EQ(stats.free_queries, 3u);
  EXPECT_EQ(stats.overlapping_queries, 1u);
  EXPECT_EQ(stats.clearance_queries, 2u);
  EXPECT_GE(stats.box_box_tests, 3u);  // the island, twice by isFree, once by overlapping
  world.resetStats();
  stats = world.stats();
  EXPECT_EQ(stats.free_queries + stats.overlapping_queries + stats.clearance_queries +
                stats.box_box_tests,
            0u);
}

TEST(BulletCollisionWorld, RejectsBadInput) {
  const BulletCollisionWorld world(studyLot());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(world.isFree({0.1, 0.1, 0.0}, -1e-9), Error);
  EXPECT_THROW(world.isFree({0.1, 0.1, 0.0}, nan), Error);
  EXPECT_THROW(world.isFree({nan, 0.1, 0.0}), Error);
  EXPECT_THROW(world.clearance({0.1, std::numeric_limits<double>::infinity(), 0.0}), Error);
  EXPECT_THROW(world.overlapping({0.1, 0.1, 0.0}, -0.5), Error);

  Scenario flat = studyLot();
  flat.source_path = "worlds/flat.yaml";
  flat.obstacles[3].box.half_extents.x() = 0.0;
  try {
    const BulletCollisionWorld bad(flat);
    ADD_FAILURE() << "a zero-width obstacle was accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("worlds/flat.yaml: obstacle 'robot_4'"));
  }
  Scenario low = studyLot();
  low.obstacles[0].height_m = -0.1;
  EXPECT_THROW(BulletCollisionWorld{low}, Error);
  Scenario no_robot = studyLot();
  no_robot.robot.height_m = 0.0;
  EXPECT_THROW(BulletCollisionWorld{no_robot}, Error);
}

TEST(BulletCollisionWorld, MovedWorldKeepsAnswering) {
  BulletCollisionWorld first(studyLot());
  BulletCollisionWorld second = std::move(first);
  EXPECT_FALSE(second.isFree({1.2, 0.65, 0.0}));
  EXPECT_TRUE(second.isFree({0.1, 0.1, 0.0}));
  first = std::move(second);
  EXPECT_FALSE(first.isFree({1.2, 0.65, 0.0}));
}

// Two worlds built from the same scenario answer identically (no hidden state between
// queries, whatever their order).
TEST(BulletCollisionWorld, AnswersDoNotDependOnQueryHistory) {
  const Scenario lot = studyLot();
  const BulletCollisionWorld a(lot);
  const BulletCollisionWorld b(lot);
  std::mt19937_64 rng(3);
  std::vector<Pose2> poses;
  for (int k = 0; k < 1000; ++k) poses.push_back(randomLotPose(rng));
  std::vector<bool> free;
  std::vector<double> clearance;
  for (const Pose2& p : poses) {
    free.push_back(a.isFree(p, 0.001));
    clearance.push_back(a.clearance(p));
  }
  for (std::size_t k = poses.size(); k-- > 0;) {
    ASSERT_EQ(b.clearance(poses[k]), clearance[k]) << describe(poses[k], 0.0);
    ASSERT_EQ(b.isFree(poses[k], 0.001), free[k]) << describe(poses[k], 0.001);
  }
}

}  // namespace
}  // namespace parksim
