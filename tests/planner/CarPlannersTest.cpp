// Every built-in planner plans for a car on the car scenes (tests/support/CarScenes.h), and each
// plan passes the test-side checker (tests/support/CarPlanChecker.h): no turning in place,
// curvature and steering within the car's limits, speed, acceleration, stops at gear changes,
// no overlap with any obstacle.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/planner/PlanScenario.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/CarScenes.h"

namespace parksim {
namespace {

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

struct Case {
  const char* planner;
  int scene;
};

class CarPlanners : public ::testing::TestWithParam<Case> {};

TEST_P(CarPlanners, PlanPassesTheCarChecker) {
  const Scenario s = testing::carScenes()[GetParam().scene];
  const BulletCollisionWorld checker(s);
  PlanSetup setup;
  setup.planner = GetParam().planner;
  setup.search.record_tree = false;
  const auto t0 = std::chrono::steady_clock::now();
  const PlanResult r = planScenario(s, checker, setup);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(r.solved()) << s.name << ": " << r.message;
  std::printf(
      "%-16s %-18s %.3f s wall, %.2f s plan (free-space bound %.2f s), %d gear changes, %d it\n",
      GetParam().planner, s.name.c_str(), wall, r.trajectory.duration(), r.free_space_bound_s,
      testing::carGearChanges(s.robot, r.trajectory), r.stats.iterations);
  {
    int stops = 0, standing = 0;
    double length = 0.0;
    bool moving = false;
    for (const TrajectoryPoint& p : r.trajectory.points) {
      const double v = 0.5 * s.robot.wheel_radius_m * (p.wheels.left_radps + p.wheels.right_radps);
      length += std::abs(v) * 0.02;
      if (std::abs(v) < 1e-9) {
        ++standing;
        if (moving) ++stops;
        moving = false;
      } else {
        moving = true;
      }
    }
    std::printf("   length %.1f m, %d stops, %d standing rows\n", length, stops, standing);
    if (std::getenv("CAR_DUMP")) {
      for (std::size_t i = 0; i < r.trajectory.points.size(); i += 10) {
        const TrajectoryPoint& p = r.trajectory.points[i];
        std::printf("     t %6.2f v %6.3f steer %6.3f  (%.2f %.2f %.1f)\n", p.t_s,
                    0.5 * s.robot.wheel_radius_m * (p.wheels.left_radps + p.wheels.right_radps),
                    p.steer_rad, p.pose.x, p.pose.y, p.pose.theta * 57.3);
      }
    }
  }
  const auto problems = testing::carPlanViolations(s, r.trajectory);
  EXPECT_TRUE(problems.empty()) << s.name << ":\n" << joined(problems);
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const char* planner : {"time-a-star", "car-a-star", "hybrid-a-star", "rrt",
                              "rrt-goal-connect", "rrt-star", "rrt-connect"}) {
    for (int k = 0; k < 6; ++k) out.push_back({planner, k});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, CarPlanners, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.planner;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name + "_" + std::to_string(info.param.scene);
                         });

}  // namespace
}  // namespace parksim
