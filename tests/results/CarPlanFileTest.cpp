// A car's trajectory.csv (docs/cars.md): the columns a car drives by, read back for a car, a
// malformed one refused naming file, line and column; and a car's plan.json keys.

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/results/episode/PlanFile.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

// Forward at 0.1 m/s on a left arc, a stop, reverse at 0.1 m/s straight, a stop: rows 0.1 s
// apart, poses integrated exactly.
Trajectory carPlan(const RobotDef& car, const Pose2& start) {
  struct Row {
    double v, steer;
  };
  const Row rows[] = {{0.0, 0.0}, {0.0, 0.05}, {0.1, 0.05}, {0.0, 0.05}, {0.0, 0.0}, {-0.1, 0.0}};
  Trajectory t;
  Pose2 pose = start;
  for (const Row& r : rows) {
    const Twist tw{r.v, r.v * std::tan(r.steer) / car.axle_distance_m};
    t.points.push_back({t.points.size() * 0.1, pose, toWheelSpeeds(tw, car), r.steer});
    pose = integrateExact(pose, tw, 0.1);
  }
  t.points.push_back({t.points.size() * 0.1, pose, {}, 0.0});
  return t;
}

std::string errorOf(const std::string& text, const RobotDef& robot) {
  try {
    parseTrajectoryCsv(text, "p.csv", robot);
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(CarPlanFile, WritesTheColumnsACarDrivesByAndReadsThemBack) {
  const RobotDef car = midSizeCar();
  const Trajectory plan = carPlan(car, {10.0, 5.0, 0.5});
  const std::filesystem::path dir = testing::testOutputDir("results");
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "car_trajectory.csv").string();
  writeTrajectoryCsv(path, plan, car);
  const std::string text = readInputFile(path, 1 << 20, "plan file");
  EXPECT_EQ(text.substr(0, text.find('\n')), "t,x,y,theta,v,steer_rad,curvature,gear");
  // Row 3 (0.2 s): 0.1 m/s forward at 0.05 rad: curvature tan(0.05) / 2.8, gear 1; row 6
  // reverses (gear -1), row 4 stands (gear 0).
  std::vector<std::string> lines;
  for (std::size_t a = 0, b; (b = text.find('\n', a)) != std::string::npos; a = b + 1) {
    lines.push_back(text.substr(a, b - a));
  }
  ASSERT_EQ(lines.size(), 8u);
  const std::string row3 = lines[3];
  EXPECT_EQ(row3.substr(row3.rfind(',') + 1), "1");
  const std::size_t c = row3.rfind(',', row3.rfind(',') - 1);
  EXPECT_NEAR(std::stod(row3.substr(c + 1)), std::tan(0.05) / 2.8, 1e-15);
  EXPECT_EQ(lines[4].substr(lines[4].rfind(',') + 1), "0");
  EXPECT_EQ(lines[6].substr(lines[6].rfind(',') + 1), "-1");

  // Read back for the car: times, poses and steering exactly, wheel speeds to rounding.
  const Trajectory back = readTrajectoryCsv(path, car);
  ASSERT_EQ(back.points.size(), plan.points.size());
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    EXPECT_EQ(back.points[i].t_s, plan.points[i].t_s);
    EXPECT_EQ(back.points[i].pose, plan.points[i].pose);
    EXPECT_EQ(back.points[i].steer_rad, plan.points[i].steer_rad);
    EXPECT_NEAR(back.points[i].wheels.left_radps, plan.points[i].wheels.left_radps, 1e-12);
    EXPECT_NEAR(back.points[i].wheels.right_radps, plan.points[i].wheels.right_radps, 1e-12);
  }
  std::filesystem::remove(path);
}

TEST(CarPlanFile, AMalformedCarPlanIsRefusedNamingFileLineAndColumn) {
  const RobotDef car = midSizeCar();
  // A differential drive's file is not a car's.
  EXPECT_EQ(errorOf("t,x,y,theta,omega_left,omega_right,v,omega\n0,0,0,0,1,1,0.3,0\n", car),
            "p.csv:1: header lacks column 'steer_rad'");
  EXPECT_EQ(errorOf("t,x,y,theta,v,steer_rad\n0,0,0,0,0,0\n0.1,0,0,0,0.1,2\n", car),
            "p.csv:3: column 'steer_rad': must be within +-pi/2 rad (a front wheel turned across "
            "the car has no curvature), got 2");
  EXPECT_EQ(errorOf("t,x,y,theta,v,steer_rad\n0,0,0,0,fast,0\n", car),
            "p.csv:2: column 'v': 'fast' is not a finite number");
  // Without curvature and gear it reads: they are for people.
  EXPECT_EQ(errorOf("t,x,y,theta,v,steer_rad\n0,0,0,0,0,0.1\n", car), "(accepted)");
  // A differential drive still reads its own columns.
  EXPECT_EQ(errorOf("t,x,y,theta,v,steer_rad\n0,0,0,0,0,0\n", RobotDef{}),
            "p.csv:1: header lacks column 'omega_left'");
}

TEST(CarPlanFile, PlanJsonSaysWhenACarChangesGearAndItsFreeSpaceBound) {
  Scenario s;
  s.robot = midSizeCar();
  s.lot = {0.0, 0.0, 30.0, 30.0};
  s.start = {10.0, 5.0, 0.0};
  const Trajectory plan = carPlan(s.robot, s.start);
  s.goal.pose = plan.points.back().pose;
  const nlohmann::json j = trajectorySummary(s, plan);
  EXPECT_EQ(j["cusps"], 1);
  ASSERT_EQ(j["cusp_times_s"].size(), 1u);
  EXPECT_DOUBLE_EQ(j["cusp_times_s"][0].get<double>(), 0.5);  // the first row in reverse
  // The plan goes 1 cm forward and 1 cm back to a pose 1e-4 rad turned: its shortest path is
  // a few millimetres to centimetres, one 0.1 s row at least; no plan is faster than the bound.
  const double bound = j["free_space_bound_s"].get<double>();
  EXPECT_GT(bound, 0.0);
  EXPECT_LE(bound, plan.duration());
  EXPECT_DOUBLE_EQ(j["duration_over_free_space_bound"].get<double>(), plan.duration() / bound);
  // A differential drive's summary has no car keys.
  Scenario d = s;
  d.robot = RobotDef{};
  EXPECT_FALSE(trajectorySummary(d, plan).contains("cusp_times_s"));
  EXPECT_FALSE(trajectorySummary(d, plan).contains("free_space_bound_s"));
}

}  // namespace
}  // namespace parksim
