// The test-side car checker (tests/support/CarPlanChecker.h) on plans built by hand: a plan a
// car can drive passes, and each rule it states fails a plan that breaks it, naming the quantity.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/model/DiffDrive.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/CarScenes.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace car_plan_checker_test {

using testing::carPlanViolations;

constexpr double kDt = 0.02;

// Rows of (speed, steer) held kDt each from `start`, then a row standing still.
struct Row {
  double v;
  double steer;
};

Trajectory rowsFrom(const RobotDef& car, const Pose2& start, const std::vector<Row>& rows) {
  Trajectory t;
  Pose2 pose = start;
  for (const Row& r : rows) {
    const double kappa = std::tan(r.steer) / car.axle_distance_m;
    const Twist twist{r.v, r.v * kappa};
    t.points.push_back({t.points.size() * kDt, pose, toWheelSpeeds(twist, car), r.steer});
    pose = integrateExact(pose, twist, kDt);
  }
  t.points.push_back({t.points.size() * kDt, pose, {}, rows.empty() ? 0.0 : rows.back().steer});
  return t;
}

// Accelerates at `accel` to `v`, holds it `cruise` rows, brakes to rest, steering `steer`
// (reached from 0 at the steering rate limit while standing first).
std::vector<Row> driveRows(const RobotDef& car, double v, int cruise, double steer = 0.0) {
  std::vector<Row> rows;
  const double steer_step = car.max_steer_rate_radps * kDt;
  for (double s = 0.0; std::abs(s) < std::abs(steer);) {
    s = std::abs(steer - s) <= steer_step ? steer : s + std::copysign(steer_step, steer);
    rows.push_back({0.0, s});
  }
  const double step = car.max_accel_mps2 * kDt;
  const int ramp = static_cast<int>(std::ceil(std::abs(v) / step));
  for (int k = 1; k <= ramp; ++k) rows.push_back({v * k / ramp, steer});
  for (int k = 0; k < cruise; ++k) rows.push_back({v, steer});
  for (int k = ramp - 1; k >= 1; --k) rows.push_back({v * k / ramp, steer});
  return rows;
}

Scenario emptyScene(const Pose2& start) {
  return testing::car_scenes::carScenario("empty", {-50.0, -50.0, 50.0, 50.0}, start, start);
}

// The scene's goal moved to where `plan` ends.
Scenario endingAt(Scenario s, const Trajectory& plan) {
  s.goal.pose = plan.points.back().pose;
  return s;
}

bool mentions(const std::vector<std::string>& problems, const std::string& what) {
  for (const std::string& p : problems) {
    if (p.find(what) != std::string::npos) return true;
  }
  return false;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

TEST(CarPlanChecker, PassesStraightDriveAndArcAtFullLock) {
  const RobotDef car = midSizeCar();
  for (double steer : {0.0, car.max_steer_rad, -car.max_steer_rad}) {
    const Trajectory plan = rowsFrom(car, {}, driveRows(car, 2.0, 50, steer));
    const auto problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
    EXPECT_TRUE(problems.empty()) << "steer " << steer << ":\n" << joined(problems);
  }
  // Reverse, then forward after a stop.
  std::vector<Row> rows = driveRows(car, -1.0, 10);
  rows.push_back({0.0, 0.0});
  for (const Row& r : driveRows(car, 1.5, 10)) rows.push_back(r);
  const Trajectory plan = rowsFrom(car, {}, rows);
  EXPECT_TRUE(carPlanViolations(endingAt(emptyScene({}), plan), plan).empty());
  EXPECT_EQ(testing::carGearChanges(car, plan), 1);
}

TEST(CarPlanChecker, FailsTurningInPlace) {
  const RobotDef car = midSizeCar();
  // The wheels turn opposite ways: the car turns without moving.
  Trajectory plan = rowsFrom(car, {}, {});
  plan.points.front().wheels = {-1.0, 1.0};
  plan.points.push_back({kDt, integrateExact({}, toTwist({-1.0, 1.0}, car), kDt), {}, 0.0});
  const auto problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "turns in place")) << joined(problems);
}

TEST(CarPlanChecker, FailsCurvatureBeyondTheSteeringLimit) {
  RobotDef car = midSizeCar();
  // Planned for a car that steers to 0.9 rad, checked for the car's 0.75.
  RobotDef sharper = car;
  sharper.max_steer_rad = 0.9;
  const Trajectory plan = rowsFrom(sharper, {}, driveRows(sharper, 1.0, 20, 0.9));
  const auto problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "curvature")) << joined(problems);
  EXPECT_TRUE(mentions(problems, "exceeds max_steer")) << joined(problems);
}

TEST(CarPlanChecker, FailsASteeringJumpAndASteerThatIsNotTheCurvature) {
  const RobotDef car = midSizeCar();
  std::vector<Row> rows = driveRows(car, 1.0, 30);
  rows[rows.size() / 2].steer = 0.2;  // one row steers 0.2 rad without the time to get there
  Trajectory plan = rowsFrom(car, {}, rows);
  auto problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "steering rate")) << joined(problems);

  plan = rowsFrom(car, {}, driveRows(car, 1.0, 30, 0.3));
  for (TrajectoryPoint& p : plan.points) p.steer_rad = 0.5 * p.steer_rad;  // half the angle
  problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "is not the steering angle's")) << joined(problems);
}

TEST(CarPlanChecker, FailsSpeedAccelerationAndAGearChangeWithoutAStop) {
  const RobotDef car = midSizeCar();
  Trajectory plan = rowsFrom(car, {}, driveRows(car, 3.0, 10));
  auto problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "m/s exceeds max_speed 2.5")) << joined(problems);

  plan = rowsFrom(car, {}, {{0.5, 0.0}, {0.5, 0.0}});  // from rest to 0.5 m/s in one row
  problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "acceleration 25 m/s^2 exceeds max_accel")) << joined(problems);

  plan = rowsFrom(car, {}, {{0.01, 0.0}, {-0.01, 0.0}});  // within the acceleration limit
  problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "the gear changes without a stop")) << joined(problems);
}

TEST(CarPlanChecker, FailsAPlanThatDoesNotFollowItsRows) {
  const RobotDef car = midSizeCar();
  Trajectory plan = rowsFrom(car, {}, driveRows(car, 1.0, 30));
  plan.points[20].pose.y += 1e-3;
  const auto problems = carPlanViolations(endingAt(emptyScene({}), plan), plan);
  EXPECT_TRUE(mentions(problems, "not where the previous row leads")) << joined(problems);
}

TEST(CarPlanChecker, FindsTheFirstOverlapOfEachShape) {
  const RobotDef car = midSizeCar();
  // Driving east from x = 0 along y = 0: the body spans y -0.971..0.971 and reaches 3.739 m
  // ahead of the reference point.
  const Trajectory plan = rowsFrom(car, {}, driveRows(car, 2.0, 100));
  const double end_x = plan.points.back().pose.x;
  const double front = end_x + car.front_overhang_m;
  const double half = 0.5 * car.width_m;
  struct Case {
    Obstacle obstacle;
    bool overlaps;
  };
  using testing::car_scenes::box;
  const std::vector<Case> cases = {
      {box("ahead", ObstacleKind::kBox, front + 0.5 + 1e-6, 0.0, 1.0, 1.0, 0.0, 1.0), false},
      {box("ahead", ObstacleKind::kBox, front + 0.5 - 1e-3, 0.0, 1.0, 1.0, 0.0, 1.0), true},
      {box("beside", ObstacleKind::kBox, 5.0, half + 0.5 + 1e-6, 2.0, 1.0, 0.0, 1.0), false},
      {box("beside", ObstacleKind::kBox, 5.0, half + 0.5 - 1e-3, 2.0, 1.0, 0.0, 1.0), true},
      // Turned 45 degrees: its corner reaches down to y = half + 0.001.
      {box("corner", ObstacleKind::kBox, 5.0, half + 0.001 + std::sqrt(0.5), 1.0, 1.0, 45.0, 1.0),
       false},
      {box("corner", ObstacleKind::kBox, 5.0, half - 0.001 + std::sqrt(0.5), 1.0, 1.0, 45.0, 1.0),
       true},
      {Obstacle::makeCircle("post", ObstacleKind::kBollard, {{6.0, half + 0.2 + 1e-6}, 0.2}, 1.0),
       false},
      {Obstacle::makeCircle("post", ObstacleKind::kBollard, {{6.0, half + 0.2 - 1e-3}, 0.2}, 1.0),
       true},
      {Obstacle::makePolygon("wedge", ObstacleKind::kIsland,
                             {{4.0, half + 0.002}, {6.0, half + 1.0}, {4.0, half + 1.0}}, 1.0),
       false},
      {Obstacle::makePolygon("wedge", ObstacleKind::kIsland,
                             {{4.0, half - 0.002}, {6.0, half + 1.0}, {4.0, half + 1.0}}, 1.0),
       true},
      // As low as the ground clearance: it passes under the car.
      {box("low", ObstacleKind::kCurb, 5.0, 0.0, 1.0, 1.0, 0.0, car.ground_clearance_m), false},
  };
  for (const Case& c : cases) {
    Scenario s = endingAt(emptyScene({}), plan);
    s.obstacles = {c.obstacle};
    const auto problems = carPlanViolations(s, plan);
    EXPECT_EQ(mentions(problems, "overlaps " + c.obstacle.name), c.overlaps)
        << c.obstacle.name << ":\n"
        << joined(problems);
    if (!c.overlaps) EXPECT_TRUE(problems.empty()) << joined(problems);
  }
}

TEST(CarPlanChecker, FailsAPlanThatEndsOutsideTheGoalOrLeavesTheLot) {
  const RobotDef car = midSizeCar();
  const Trajectory plan = rowsFrom(car, {}, driveRows(car, 2.0, 100));
  Scenario s = endingAt(emptyScene({}), plan);
  s.goal.pose.x += 0.06;
  EXPECT_TRUE(mentions(carPlanViolations(s, plan), "from the goal"));
  s = endingAt(emptyScene({}), plan);
  s.lot.x_max_m = 2.0;
  EXPECT_TRUE(mentions(carPlanViolations(s, plan), "leaves the lot"));
}

TEST(CarPlanChecker, SceneStartsAndGoalsAreFree) {
  // A plan of one row standing at the start: every scene's start is free, and so is its goal.
  for (const Scenario& s : testing::carScenes()) {
    Trajectory at_start;
    at_start.points.push_back({0.0, s.start, {}, 0.0});
    Scenario start_goal = s;
    start_goal.goal.pose = s.start;
    EXPECT_TRUE(carPlanViolations(start_goal, at_start).empty()) << s.name;
    Trajectory at_goal;
    at_goal.points.push_back({0.0, s.goal.pose, {}, 0.0});
    Scenario goal_start = s;
    goal_start.start = s.goal.pose;
    EXPECT_TRUE(carPlanViolations(goal_start, at_goal).empty()) << s.name;
  }
}

}  // namespace car_plan_checker_test
}  // namespace parksim
