// A car's episodes (sim/Episode.h with RobotDef::isCar): the default controller tracks a
// hand-made plan (arc, straight, reverse) at up to 2.5 m/s; executed rows carry the steering.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/sim/episode/Episode.h"
#include "tests/sim/CarTestSupport.h"

namespace parksim {
namespace {

// Forward to 2.5 m/s, a left arc at 0.5 rad (5.1 m radius), straight, stop; then reverse at
// 1.5 m/s steering right, stop: 20 m forward and a gear change, within the car's limits.
Trajectory arcStraightReverse(const Scenario& s) {
  return testing::carPlan(s.start,
                          {{2.5, 0.0, 1.0},
                           {2.5, 0.5, 3.0},
                           {2.5, 0.0, 2.0},
                           {0.0, 0.0, 0.5},
                           {-1.5, -0.4, 2.0},
                           {0.0, 0.0, 0.0}},
                          s.robot);
}

TEST(CarEpisodeTest, DefaultControllerTracksArcStraightAndReverse) {
  const Scenario s = testing::carLot({20.0, 30.0, 0.0});
  const Trajectory plan = arcStraightReverse(s);
  double top = 0.0;
  for (const TrajectoryPoint& p : plan.points) {
    top = std::max(top, std::abs(toTwist(p.wheels, s.robot).v_mps));
  }
  ASSERT_NEAR(top, 2.5, 1e-9);
  ASSERT_EQ(plan.cusps(s.robot), 1);

  for (const TrackingMode mode : {TrackingMode::kOpen, TrackingMode::kClosed}) {
    ExecutionDef def;
    def.tracking = mode;
    const EpisodeResult r = runEpisode(s, plan, def);
    const EpisodeMetrics& m = r.metrics;
    double worst_steer = 0.0;
    for (const ExecutedRow& row : r.rows) {
      worst_steer = std::max(worst_steer, std::abs(row.steer_rad - row.steer_ref_rad));
    }
    std::printf(
        "%s loop, %.1f s plan: max error %.2f mm, rms %.2f mm, final %.2f mm, max heading "
        "%.3f deg, contacts %d, steering off the plan's by at most %.4f rad\n",
        toString(mode), m.plan_duration_s, m.max_pos_err_m * 1e3, m.rms_pos_err_m * 1e3,
        m.final_pos_err_m * 1e3, m.max_heading_err_deg, m.contacts, worst_steer);
    EXPECT_EQ(m.contacts, 0);
    EXPECT_TRUE(m.ended_at_rest);
    if (mode == TrackingMode::kClosed) {
      // Issue 38's target: within 20 mm all the way at up to 2.5 m/s.
      EXPECT_LE(m.max_pos_err_m, 0.020);
      EXPECT_LE(m.final_pos_err_m, 0.005);
    }
  }
}

TEST(CarEpisodeTest, RowsRecordCommandedAndMeasuredSteering) {
  const Scenario s = testing::carLot({20.0, 30.0, 0.0});
  const Trajectory plan = arcStraightReverse(s);
  const EpisodeResult r = runEpisode(s, plan);
  ASSERT_GT(r.rows.size(), 100U);
  double largest_cmd = 0.0;
  double largest = 0.0;
  for (const ExecutedRow& row : r.rows) {
    largest_cmd = std::max(largest_cmd, row.steer_cmd_rad);
    largest = std::max(largest, row.steer_rad);
    // The steering never leaves the car's range; the command is the controller's.
    EXPECT_LE(std::abs(row.steer_rad), s.robot.max_steer_rad + 1e-3);
  }
  // The plan's left arc at 0.5 rad: commanded and measured.
  EXPECT_NEAR(largest_cmd, 0.5, 0.02);
  EXPECT_NEAR(largest, 0.5, 0.02);

  // executed.csv: a car's three steering columns last; a differential drive's file without.
  const std::string csv = executedCsv(r.rows, false, true);
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header,
            "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,"
            "omega_right,pos_err,heading_err,steer_ref,steer_cmd,steer");
  const std::vector<DataColumn> columns = executedColumns(r.rows, false, true);
  ASSERT_NE(findColumn(columns, "steer"), nullptr);
  EXPECT_EQ(findColumn(columns, "steer")->values.back(), r.rows.back().steer_rad);
  EXPECT_EQ(executedCsv(r.rows).find("steer"), std::string::npos);
}

}  // namespace
}  // namespace parksim
