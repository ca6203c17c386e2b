// The controller `command` driving a car (issue 38): its reset names the drive and the car's
// limits, its ticks carry the steering, and it answers a speed (or an acceleration) and a
// steering angle; answers beyond the car's limits are a controller error.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/usercode/CommandController.h"
#include "parksim/usercode/CommandLine.h"
#include "tests/sim/CarTestSupport.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

TEST(CarCommandControllerTest, ACarsTickLineCarriesItsSteering) {
  ControllerInput in;
  in.tick = 3;
  in.steer_rad = 0.25;
  in.reference_steer_rad = -0.5;
  in.commanded_speed_mps = 1.5;
  const std::string line = tickLine(in, true);
  const std::string tail = " 0 0.25 -0.5 1.5\n";  // plan_ended, then the car's three
  EXPECT_EQ(line.substr(line.size() - tail.size()), tail);
  EXPECT_EQ(tickLine(in), tickLine(in, false));
  EXPECT_EQ(tickLine(in).find("0.25"), std::string::npos);
}

TEST(CarCommandControllerTest, CarAnswersAreAKeywordAndTwoNumbers) {
  const auto speed = parseCarAnswer("speed 1.5 -0.25\r");
  ASSERT_TRUE(speed.has_value());
  EXPECT_EQ(speed->mode, CarCommand::Mode::kSpeed);
  EXPECT_EQ(speed->speed_mps, 1.5);
  EXPECT_EQ(speed->steer_rad, -0.25);
  const auto accel = parseCarAnswer("  accel\t-0.5 0.1");
  ASSERT_TRUE(accel.has_value());
  EXPECT_EQ(accel->mode, CarCommand::Mode::kAcceleration);
  EXPECT_EQ(accel->accel_mps2, -0.5);
  EXPECT_EQ(accel->steer_rad, 0.1);
  for (const char* bad :
       {"", "speed", "speed 1", "speed 1 2 3", "1 2", "fast 1 2", "speed1 2", "accel a b"}) {
    EXPECT_FALSE(parseCarAnswer(bad).has_value()) << bad;
  }
}

struct Drive {
  EpisodeResult result;
  nlohmann::json reset;
};

// The test car's arc, straight and reverse, driven by a Python process that keeps its reset
// message and answers `answer` (a Python expression of the tick's tokens f).
Drive driveWith(const std::string& name, const std::string& answer) {
  const fs::path dir = testing::testOutputDir("command/car_" + name);
  fs::remove_all(dir);
  ensureDirectory(dir.string());
  const fs::path file = dir / "reset.json";
  const std::string program =
      "import sys\n"
      "open(sys.argv[1], 'w').write(sys.stdin.readline()[6:])\n"
      "print('ready', flush=True)\n"
      "for line in sys.stdin:\n"
      "    f = line.split()\n"
      "    print(" +
      answer + ", flush=True)\n";
  const Scenario s = testing::carLot({20.0, 30.0, 0.0});
  const Trajectory plan = testing::carPlan(
      s.start, {{2.5, 0.3, 1.0}, {0.0, 0.0, 0.0}, {-1.0, 0.0, 0.5}, {0.0, 0.0, 0.0}}, s.robot);
  EpisodeController controller;
  controller.controller = commandControllerEntry().make(
      {{kCommandParam, quoteCommandLine({"python3", "-c", program, file.string()})}});
  controller.name = kCommandController;
  controller.trusted = false;
  Drive out;
  out.result = runEpisode(s, plan, {}, {}, 1.0 / 30.0, std::move(controller));
  std::ifstream in(file);
  out.reset = nlohmann::json::parse(in);
  return out;
}

TEST(CarCommandControllerTest, AProcessDrivesACarBySpeedAndSteering) {
  // Tokens: 13 the plan's speed, 19 its feed-forward steering (kTickFields, kCarTickFields).
  const Drive d = driveWith("speed", "'speed', f[13], f[19]");
  const EpisodeMetrics& m = d.result.metrics;
  ASSERT_TRUE(m.controller_error.empty()) << m.controller_error;
  // Feed-forward alone: as the open loop (CarEpisodeTest), within a few centimetres.
  EXPECT_LT(m.max_pos_err_m, 0.05);
  EXPECT_TRUE(m.ended_at_rest);
  EXPECT_EQ(d.reset["drive"], "car");
  EXPECT_EQ(d.reset["tick_fields"].size(), kTickFields.size() + kCarTickFields.size());
  EXPECT_EQ(d.reset["tick_fields"][18], "ref_steer_rad");  // token 19: "tick" comes first
  const nlohmann::json& robot = d.reset["world"]["robot"];
  EXPECT_EQ(robot["drive"], "car");
  EXPECT_EQ(robot["axle_distance_m"], 2.8);
  EXPECT_EQ(robot["max_steer_rad"], 0.75);
  EXPECT_EQ(robot["max_steer_rate_radps"], 0.5);
  EXPECT_EQ(robot["max_speed_mps"], 2.5);
  EXPECT_EQ(robot["max_accel_mps2"], 1.0);
  EXPECT_EQ(d.reset["plan"]["columns"].back(), "steer_rad");
}

TEST(CarCommandControllerTest, AnswersBeyondTheCarsLimitsAreControllerErrors) {
  const Drive fast = driveWith("fast", "'speed 9', f[19]");
  EXPECT_NE(fast.result.metrics.controller_error.find(
                "returned speed 9 at t = 0.000 s: beyond robot.max_speed_mps 2.5"),
            std::string::npos)
      << fast.result.metrics.controller_error;
  const Drive lock = driveWith("lock", "'accel 0 1'");
  EXPECT_NE(lock.result.metrics.controller_error.find("steering angle 1 at t = 0.000 s: beyond "
                                                      "robot.max_steer_rad 0.75"),
            std::string::npos)
      << lock.result.metrics.controller_error;
  const Drive garbage = driveWith("garbage", "'left'");
  EXPECT_NE(garbage.result.metrics.controller_error.find(
                "expected 'speed V STEER' (m/s, rad), 'accel A STEER' (m/s^2, rad) or "
                "'LEFT RIGHT'"),
            std::string::npos)
      << garbage.result.metrics.controller_error;
}

}  // namespace
}  // namespace parksim
