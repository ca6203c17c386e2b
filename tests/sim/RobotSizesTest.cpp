// Issue 30's robots of any size: the study's 85 mm robot, 0.3 m and 1 m robots in the study's
// lot scaled to them (tests/sim/worlds), and the 4.25 x 2.43 m car at 3 m/s in its lot of parked
// cars (worlds/car_lot.yaml) follow their default plans closed loop without contact, to within
// the error the tracking loop predicts, and park.
//
// The bound. The tracking controller (sim/control/TrackingController.h) corrects the along-track
// error at the rate w = k_x and has the cross-track/heading loop at the same bandwidth at the
// plan's speed, so the error dynamics are the same for every robot size and speed. What it corrects
// is the drive's lag: a velocity motor reaches its target one physics step dt after it is set,
// so while the plan accelerates at a the robot's speed falls short of the plan's by a dt, which
// the loop holds at an error of e = a dt / w. The plan accelerates at most at the robot's wheel
// acceleration limit (max_wheel_accel x wheel radius): 0.8 m/s^2 for the study's robot, 2.8
// for the 0.3 and 1 m robots, 3 for the car, which at dt = 1/240 s and w = 10 rad/s is 0.33,
// 1.18 and 1.25 mm. Measured: 0.06, 1.17, 1.38 and 1.40 mm; the test allows twice the
// prediction (the heading loop adds its own share in the turns). The error is thus independent
// of the robot's size and of its top speed, and in proportion to its acceleration: relative to
// the size, a car's is 1.4 mm in 4.25 m, against the 0.5 mm x size / 85 mm clearance its plans
// keep (the motion checks' margin, core/model/Scenario.h).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/control/TrackingController.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

struct SizeCase {
  const char* world;  // from the source directory
  const char* name;
};

std::string caseName(const ::testing::TestParamInfo<SizeCase>& info) { return info.param.name; }

class RobotSizes : public ::testing::TestWithParam<SizeCase> {};

TEST_P(RobotSizes, TheDefaultPlanIsTrackedClosedLoopWithoutContactWithinTheLoopsPrediction) {
  const Scenario s = loadScenario(parksim::testing::sourceDir() + "/" + GetParam().world);
  const BulletCollisionWorld checker(s);
  PlanSetup setup;
  setup.search.record_tree = false;
  const PlanResult plan = planScenario(s, checker, setup);
  ASSERT_TRUE(plan.solved()) << plan.message;

  const EpisodeResult r = runEpisode(s, plan.trajectory);
  const EpisodeMetrics& m = r.metrics;
  double top = 0.0;
  for (const TrajectoryPoint& p : plan.trajectory.points) {
    top = std::max(top, std::abs(toTwist(p.wheels, s.robot).v_mps));
  }
  const double dt = s.physics.time_step_s;
  const double w = trackingGains(TrackingDef{}, s.robot, top, dt, 0.0).k_x;
  const double a = s.robot.max_wheel_accel_radps2 * s.robot.wheel_radius_m;
  const double predicted = a * dt / w;
  std::printf(
      "%s: %.3f m robot at %.2f m/s, max error %.3f mm (a dt / w = %.3f mm), final "
      "%.3f mm, contacts %d, %.2f s simulated\n",
      GetParam().name, s.robot.size(), top, m.max_pos_err_m * 1e3, predicted * 1e3,
      m.final_pos_err_m * 1e3, m.contacts, m.sim_time_s);
  EXPECT_EQ(m.contacts, 0) << m.first_contact_body << " at " << m.first_contact_t_s << " s";
  EXPECT_LE(m.max_pos_err_m, 2.0 * predicted);
  EXPECT_TRUE(m.goal_reached);
  EXPECT_TRUE(m.ended_at_rest);
}

INSTANTIATE_TEST_SUITE_P(Sim, RobotSizes,
                         ::testing::Values(SizeCase{"worlds/head_in.yaml", "study_85mm"},
                                           SizeCase{"tests/sim/worlds/head_in_30cm.yaml",
                                                    "robot_30cm"},
                                           SizeCase{"tests/sim/worlds/head_in_1m.yaml", "robot_1m"},
                                           SizeCase{"worlds/car_lot.yaml", "car_4m"}),
                         caseName);

// Bullet gives a wheel joint whose axle inertia is below SIMD_EPSILON (1.19e-7 kg m^2 in single
// precision) no acceleration: it never turns. For the study's 20 mm wheels (a sphere's 2/5 m r^2)
// that is a wheel under 0.745 g: at 0.5 g the world is refused with the fields to change, at
// 1 g the wheels follow their motors. The 1 cm micro robot's 2 mm, 0.1 g wheels are refused.
TEST(RobotSizes, AWheelBulletWouldHoldStillIsRefused) {
  Scenario s = loadScenario(parksim::testing::sourceDir() + "/worlds/head_in.yaml");
  const double threshold_kg =
      1.1920929e-7 / (0.4 * s.robot.wheel_radius_m * s.robot.wheel_radius_m);
  EXPECT_NEAR(threshold_kg, 7.45e-4, 1e-6);
  s.physics.wheel_mass_kg = 0.5e-3;
  try {
    DynamicsWorld world(s, s.start);
    ADD_FAILURE() << "a 0.5 g wheel was simulated";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("axle inertia, 8e-08 kg m^2"), std::string::npos) << what;
    EXPECT_NE(what.find("physics.wheel_mass_kg"), std::string::npos) << what;
    EXPECT_NE(what.find("robot.wheel_radius"), std::string::npos) << what;
  }
  s.physics.wheel_mass_kg = 1e-3;
  DynamicsWorld world(s, s.start);
  world.setWheelTargets({2.0, 2.0});
  for (int i = 0; i < 240; ++i) world.step();
  EXPECT_NEAR(world.robot().wheels.left_radps, 2.0, 0.1);
  EXPECT_NEAR(world.robot().wheels.right_radps, 2.0, 0.1);

  // The micro robot is refused when its world is read (PhysicalRanges.h, jointInertiaProblem).
  EXPECT_THROW(
      (void)loadScenario(parksim::testing::sourceDir() + "/tests/sim/worlds/head_in_1cm.yaml"),
      Error);
}

}  // namespace
}  // namespace parksim
