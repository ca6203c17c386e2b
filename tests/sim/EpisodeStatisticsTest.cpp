// Running maxima and RMS values of an episode's measured instants.

#include "parksim/sim/episode/EpisodeStatistics.h"

#include <cmath>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"

namespace parksim {
namespace {

ExecutedRow row(double pos_err, double heading_err, double slip_left, double slip_right) {
  ExecutedRow r;
  r.pos_err_m = pos_err;
  r.heading_err_rad = heading_err;
  r.slip_mps = {slip_left, slip_right};
  r.est_pos_err_m = 2.0 * pos_err;
  r.est_heading_err_rad = -heading_err;
  r.torque_nm = {0.01, -0.03};
  r.effort = {-0.5, 0.2};
  return r;
}

TEST(EpisodeStatistics, MaximaAndRmsOverEveryInstant) {
  EpisodeStatistics s;
  s.add(row(0.003, -0.02, 0.0, 0.002), false);
  s.add(row(0.004, 0.01, -0.0005, 0.0), false);
  EXPECT_EQ(s.count(), 2);
  EpisodeMetrics m;
  s.report(m);
  EXPECT_DOUBLE_EQ(m.max_pos_err_m, 0.004);
  EXPECT_DOUBLE_EQ(m.rms_pos_err_m, std::sqrt((0.003 * 0.003 + 0.004 * 0.004) / 2.0));
  EXPECT_DOUBLE_EQ(m.max_heading_err_deg, radToDeg(0.02));
  EXPECT_DOUBLE_EQ(m.rms_heading_err_deg, radToDeg(std::sqrt((0.02 * 0.02 + 0.01 * 0.01) / 2.0)));
  // Slip: both wheels of every instant; one of the four slips by more than 1 mm/s.
  EXPECT_DOUBLE_EQ(m.max_slip_mps, 0.002);
  EXPECT_DOUBLE_EQ(m.rms_slip_mps, std::sqrt((0.002 * 0.002 + 0.0005 * 0.0005) / 4.0));
  EXPECT_DOUBLE_EQ(m.slip_fraction, 0.25);
  // The ideal robot has no estimate and no motors.
  EXPECT_EQ(m.max_est_pos_err_m, 0.0);
  EXPECT_EQ(m.max_motor_torque_nm, 0.0);
  EXPECT_EQ(m.max_motor_effort, 0.0);
}

TEST(EpisodeStatistics, UnderARealismAlsoTheEstimateAndTheMotors) {
  EpisodeStatistics s;
  s.add(row(0.001, 0.01, 0.0, 0.0), true);
  s.add(row(0.002, -0.03, 0.0, 0.0), true);
  EpisodeMetrics m;
  s.report(m);
  EXPECT_DOUBLE_EQ(m.max_est_pos_err_m, 0.004);
  EXPECT_DOUBLE_EQ(m.rms_est_pos_err_m, std::sqrt((0.002 * 0.002 + 0.004 * 0.004) / 2.0));
  EXPECT_DOUBLE_EQ(m.max_est_heading_err_deg, radToDeg(0.03));
  EXPECT_DOUBLE_EQ(m.max_motor_torque_nm, 0.03);
  EXPECT_DOUBLE_EQ(m.max_motor_effort, 0.5);
}

}  // namespace
}  // namespace parksim
