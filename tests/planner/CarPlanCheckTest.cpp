// The plan check's car rules (planner/PlanCheck.h, docs/cars.md): each is broken by a
// hand-made plan that keeps the others, and is named with its time, quantity and limit. A
// differential drive's plans are judged as before.

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/FootprintChecker.h"
#include "parksim/planner/base/PlanCheck.h"

namespace parksim {
namespace {

constexpr double kDt = 0.1;

// No obstacles: the car rules alone are under test (the lot still bounds the reference point).
class OpenLot : public FootprintChecker {
 public:
  bool isFree(const Pose2&, double) const override { return true; }
};

// A row held kDt: the reference point's speed and the steering angle; `omega` replaces the
// steering angle's yaw rate when given (a plan whose wheels and steering disagree).
struct Row {
  double v = 0.0;
  double steer = 0.0;
  std::optional<double> omega = std::nullopt;
};

Scenario carScenario() {
  Scenario s;
  s.robot = midSizeCar();
  s.lot = {0.0, 0.0, 100.0, 100.0};
  s.start = {50.0, 50.0, 0.0};
  return s;
}

// The rows' plan from the scenario's start, ending in a row at rest that keeps the last
// steering angle; the goal is set where it ends.
Trajectory planOf(Scenario& s, const std::vector<Row>& rows) {
  const RobotDef& car = s.robot;
  Trajectory t;
  Pose2 pose = s.start;
  for (const Row& r : rows) {
    const Twist tw{r.v, r.omega ? *r.omega : r.v * std::tan(r.steer) / car.axle_distance_m};
    t.points.push_back({t.points.size() * kDt, pose, toWheelSpeeds(tw, car), r.steer});
    pose = integrateExact(pose, tw, kDt);
  }
  t.points.push_back({t.points.size() * kDt, pose, {}, rows.empty() ? 0.0 : rows.back().steer});
  s.goal.pose = pose;
  return t;
}

// Steers from `from` to `to` at the rate limit while standing.
void steerStanding(const RobotDef& car, double from, double to, std::vector<Row>& rows) {
  const double step = car.max_steer_rate_radps * kDt;
  double s = from;
  while (s != to) {
    s = std::abs(to - s) <= step ? to : s + std::copysign(step, to - s);
    rows.push_back({0.0, s});
  }
}

// Accelerates at the limit to `v` (either sign), holds it `cruise` rows and brakes to rest,
// steering `steer` throughout.
void drive(const RobotDef& car, double v, int cruise, double steer, std::vector<Row>& rows) {
  const int ramp = static_cast<int>(std::ceil(std::abs(v) / (car.max_accel_mps2 * kDt)));
  for (int k = 1; k <= ramp; ++k) rows.push_back({v * k / ramp, steer});
  for (int k = 0; k < cruise; ++k) rows.push_back({v, steer});
  for (int k = ramp - 1; k >= 0; --k) rows.push_back({v * k / ramp, steer});
}

std::string violationOf(Scenario& s, const std::vector<Row>& rows) {
  const Trajectory plan = planOf(s, rows);
  const std::optional<PlanViolation> v = checkPlan(s, OpenLot(), plan);
  return v ? v->reason : "(valid)";
}

// Forward on the tightest left arc, stop, steer right while standing, reverse on the tightest
// right arc, stop, steer straight: at every limit, and valid.
std::vector<Row> aDrivableManoeuvre(const RobotDef& car) {
  std::vector<Row> rows;
  const double lock = car.max_steer_rad;
  steerStanding(car, 0.0, lock, rows);
  drive(car, 2.5, 10, lock, rows);
  steerStanding(car, lock, -lock, rows);
  drive(car, -2.5, 10, -lock, rows);
  steerStanding(car, -lock, 0.0, rows);
  return rows;
}

TEST(CarPlanCheck, APlanAtEveryLimitIsValid) {
  Scenario s = carScenario();
  EXPECT_EQ(violationOf(s, aDrivableManoeuvre(s.robot)), "(valid)");
}

TEST(CarPlanCheck, TurningInPlaceIsRefused) {
  Scenario s = carScenario();
  // Standing, the rear wheels turn opposite ways: a differential drive's spin.
  const std::string why = violationOf(s, {{0.0, 0.0, 0.3}, {0.0, 0.0, 0.3}});
  EXPECT_EQ(why.rfind("at t = 0.000 s (x 50.000 m, y 50.000 m, 0.0 deg) the car turns in place: "
                      "yaw rate 0.3 rad/s at speed 0 m/s",
                      0),
            0u)
      << why;
  EXPECT_NE(why.find("0.3327 1/m"), std::string::npos) << why;  // tan(0.75) / 2.8
}

TEST(CarPlanCheck, CurvatureBeyondTheSteeringLimitIsRefused) {
  Scenario s = carScenario();
  const RobotDef& car = s.robot;
  const double kappa_max = std::tan(car.max_steer_rad) / car.axle_distance_m;
  // At full lock the wheels turn 1 % tighter than the steering allows.
  std::vector<Row> rows;
  steerStanding(car, 0.0, car.max_steer_rad, rows);
  const std::size_t at = rows.size();
  rows.push_back({0.05, car.max_steer_rad, 0.05 * kappa_max * 1.01});
  rows.push_back({0.0, car.max_steer_rad});
  const std::string why = violationOf(s, rows);
  ASSERT_EQ(at, 15u);  // 0.75 rad at 0.5 rad/s
  EXPECT_EQ(why.rfind("at t = 1.500 s", 0), 0u) << why;
  EXPECT_NE(why.find("the curvature 0.336 1/m (radius 2.976 m) exceeds the car's "
                     "tan(max_steer) / axle_distance = 0.3327 1/m (radius 3.006 m)"),
            std::string::npos)
      << why;
  // Within the stated slack (a millionth of the limit) it passes.
  rows[at].omega = 0.05 * kappa_max * (1.0 + 0.5e-6);
  EXPECT_EQ(violationOf(s, rows), "(valid)");
}

TEST(CarPlanCheck, WheelsThatDisagreeWithTheSteeringAreRefused) {
  Scenario s = carScenario();
  // Wheels straight, yet the wheel speeds curve at 0.1 1/m (within the car's limit).
  const std::string why = violationOf(s, {{0.05, 0.0, 0.005}, {0.0, 0.0}});
  EXPECT_NE(why.find("the curvature 0.1 1/m of the wheel speeds is not the steering angle's: "
                     "tan(0 rad) / axle_distance = 0 1/m"),
            std::string::npos)
      << why;
}

TEST(CarPlanCheck, SteeringBeyondItsLimitIsRefusedEvenStanding) {
  Scenario s = carScenario();
  std::vector<Row> rows;
  steerStanding(s.robot, 0.0, s.robot.max_steer_rad + 0.04, rows);
  const std::string why = violationOf(s, rows);
  EXPECT_NE(why.find("the steering angle 0.79 rad (45.26 deg) exceeds robot.max_steer_deg 42.97"),
            std::string::npos)
      << why;
}

TEST(CarPlanCheck, SteeringFasterThanItsRateIsRefusedEvenStanding) {
  Scenario s = carScenario();
  // 0.2 rad in one 0.1 s row: 2 rad/s, four times the car's 0.5 rad/s.
  const std::string why = violationOf(s, {{0.0, 0.0}, {0.0, 0.2}, {0.0, 0.2}});
  EXPECT_EQ(why.rfind("at t = 0.100 s", 0), 0u) << why;
  EXPECT_NE(why.find("the steering angle changes by 0.2 rad in 0.1 s: 2 rad/s exceeds "
                     "robot.max_steer_rate_degps 28.65 (0.5 rad/s; steering while stopped takes "
                     "time too)"),
            std::string::npos)
      << why;
  // The first row steers from straight wheels too.
  EXPECT_NE(violationOf(s, {{0.0, 0.2}}).find("the steering angle changes by 0.2 rad"),
            std::string::npos);
}

TEST(CarPlanCheck, SpeedBeyondItsLimitIsRefused) {
  Scenario s = carScenario();
  std::vector<Row> rows;
  drive(s.robot, 2.6, 3, 0.0, rows);  // accelerates within the limit, past 2.5 m/s
  const std::string why = violationOf(s, rows);
  EXPECT_NE(why.find("the speed 2.6 m/s exceeds robot.max_speed_mps 2.5"), std::string::npos)
      << why;
}

TEST(CarPlanCheck, AccelerationBeyondItsLimitIsRefused) {
  Scenario s = carScenario();
  // 0.1 m/s^2 ... then 0.3 m/s in one row: 2 m/s^2.
  const std::string why = violationOf(s, {{0.1, 0.0}, {0.3, 0.0}, {0.2, 0.0}, {0.1, 0.0}});
  EXPECT_EQ(why.rfind("at t = 0.100 s", 0), 0u) << why;
  EXPECT_NE(why.find("the speed changes by 0.2 m/s in 0.1 s: 2 m/s^2 exceeds "
                     "robot.max_accel_mps2 1"),
            std::string::npos)
      << why;
  // Braking counts too: the plan ends at rest.
  EXPECT_NE(violationOf(s, {{0.1, 0.0}, {0.2, 0.0}}).find("the speed changes by 0.2 m/s"),
            std::string::npos);
}

TEST(CarPlanCheck, GearChangesStop) {
  Scenario s = carScenario();
  // Forward at 4 cm/s, then reverse at 4 cm/s: within the acceleration, but no stop between.
  const std::string why = violationOf(s, {{0.04, 0.0}, {-0.04, 0.0}});
  EXPECT_EQ(why.rfind("at t = 0.100 s", 0), 0u) << why;
  EXPECT_NE(why.find("the car changes gear from forward to reverse without stopping (speed "
                     "0.04 m/s, then -0.04 m/s); a gear change stops"),
            std::string::npos)
      << why;
  // With a row at rest between, it is valid.
  EXPECT_EQ(violationOf(s, {{0.04, 0.0}, {0.0, 0.0}, {-0.04, 0.0}}), "(valid)");
}

TEST(CarPlanCheck, ADifferentialDriveStillTurnsInPlace) {
  Scenario s = carScenario();
  s.robot = RobotDef{};
  s.robot.max_wheel_accel_radps2 = 1000.0;
  // A spin at 1 rad/s: wheel speeds within the study robot's 10 rad/s.
  EXPECT_EQ(violationOf(s, {{0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}}), "(valid)");
}

}  // namespace
}  // namespace parksim
