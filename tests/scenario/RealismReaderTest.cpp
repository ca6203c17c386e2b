#include "parksim/scenario/world/RealismReader.h"
#include "parksim/scenario/world/World.h"

#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace realism_reader_test {

// Lines 1-5 of every test document.
constexpr std::string_view kWorld =
    "format: parksim-world/1\n"
    "name: t\n"
    "lot: {x_min: 0, y_min: 0, x_max: 2, y_max: 2}\n"
    "start: [0.5, 0.5, 0]\n"
    "goal: {pose: [1.5, 1.5, 90]}\n";

std::string errorOf(std::string_view extra) {
  const std::string text = std::string(kWorld) + std::string(extra);
  try {
    parseWorld(text, "t.yaml");
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(RealismReader, AbsentSectionsLeaveTheDefaults) {
  const WorldRealism w = parseWorld(kWorld, "t.yaml").sections;
  EXPECT_FALSE(w.has_realism);
  EXPECT_FALSE(w.has_tolerance);
  EXPECT_FALSE(w.realism.active());
}

TEST(RealismReader, DefaultToleranceScalesWithTheRobotsSize) {
  // The study's robot keeps today's numbers exactly.
  const TrackingTolerance study = parseWorld(kWorld, "t.yaml").sections.tolerance;
  EXPECT_EQ(study.max_pos_err_m, 0.005);
  EXPECT_EQ(study.goal_pos_err_m, 0.003);
  EXPECT_EQ(study.goal_heading_err_deg, 1.5);
  EXPECT_EQ(study.max_contacts, 0);
  EXPECT_EQ(study.max_parked_displacement_m, 1e-4);
  // A 4.25 m robot is 50 study robots (85 mm) long: 250 mm, 150 mm and 5 mm, the same degrees.
  const std::string big = std::string(kWorld) +
                          "robot: {length: 4.25, width: 2.43, front_overhang: 2.125, "
                          "wheel_base: 2.2, wheel_radius: 0.3, max_wheel_accel_radps2: 1}\n";
  const TrackingTolerance t = parseWorld(big, "t.yaml").sections.tolerance;
  EXPECT_NEAR(t.max_pos_err_m, 0.25, 1e-12);
  EXPECT_NEAR(t.goal_pos_err_m, 0.15, 1e-12);
  EXPECT_NEAR(t.max_parked_displacement_m, 0.005, 1e-12);
  EXPECT_EQ(t.goal_heading_err_deg, 1.5);
  EXPECT_EQ(t.max_contacts, 0);
  // A section's bound replaces one default; the others stay scaled.
  const TrackingTolerance mixed =
      parseWorld(big + "tolerance: {max_pos_err_m: 0.02}\n", "t.yaml").sections.tolerance;
  EXPECT_EQ(mixed.max_pos_err_m, 0.02);
  EXPECT_NEAR(mixed.goal_pos_err_m, 0.15, 1e-12);
  // The mid-size car: its 4.689 m length over 85 mm.
  const TrackingTolerance car =
      parseWorld(std::string(kWorld) + "robot: {drive: car}\n", "t.yaml").sections.tolerance;
  EXPECT_NEAR(car.max_pos_err_m, 0.005 * 4.689 / 0.085, 1e-12);
}

TEST(RealismReader, APresetWithOverridesAndATolerance) {
  const std::string text = std::string(kWorld) +
                           "realism:\n"
                           "  preset: lab\n"
                           "  pose_sensor: {latency_s: 0.075, heading_noise_deg: 0.5}\n"
                           "  calibration: {track_error_pct: -1.5}\n"
                           "  control: {rate_hz: 30}\n"
                           "tolerance: {max_pos_err_m: 0.01, require_goal_reached: true}\n";
  EXPECT_NO_THROW(parseScenario(text, "t.yaml"));
  const WorldRealism w = parseWorld(text, "t.yaml").sections;
  ASSERT_TRUE(w.has_realism);
  EXPECT_EQ(w.realism.name, "lab+world");
  EXPECT_DOUBLE_EQ(w.realism.pose_sensor.latency_s, 0.075);
  EXPECT_DOUBLE_EQ(w.realism.pose_sensor.heading_noise_rad, degToRad(0.5));
  EXPECT_DOUBLE_EQ(w.realism.pose_sensor.rate_hz, presetRealism("lab").pose_sensor.rate_hz);
  EXPECT_DOUBLE_EQ(w.realism.calibration.track_error_pct, -1.5);
  EXPECT_DOUBLE_EQ(w.realism.control.rate_hz, 30.0);
  EXPECT_TRUE(w.realism.motor.enabled);
  ASSERT_TRUE(w.has_tolerance);
  EXPECT_DOUBLE_EQ(w.tolerance.max_pos_err_m, 0.01);
  EXPECT_TRUE(w.tolerance.require_goal_reached);
  EXPECT_DOUBLE_EQ(w.tolerance.goal_pos_err_m, TrackingTolerance{}.goal_pos_err_m);
}

TEST(RealismReader, BadEntriesAreLocated) {
  EXPECT_EQ(errorOf("realism: {preset: lub}\n"),
            "t.yaml:6: realism.preset: unknown preset \"lub\"; expected one of: ideal, lab, "
            "odometry");
  EXPECT_EQ(errorOf("realism:\n  motor: {time_constant_s: 0}\n"),
            "t.yaml:7: realism.motor.time_constant_s: must be positive, got 0");
  EXPECT_EQ(errorOf("realism:\n  estimator: {kind: kalman}\n"),
            "t.yaml:7: realism.estimator.kind: unknown estimator \"kalman\"; expected one of: "
            "truth, odometry, fused");
  EXPECT_NE(errorOf("realism: {estimator: {kind: fused}}\n").find("needs the pose sensor"),
            std::string::npos);
  EXPECT_NE(errorOf("tolerance: {max_pos_err: 1}\n").find("t.yaml:6: tolerance"),
            std::string::npos);
  EXPECT_EQ(errorOf("realism: {pose_sensor: {dropout_probability: 2}}\n"),
            "t.yaml:6: realism.pose_sensor.dropout_probability: must lie in [0, 1], got 2");
}

}  // namespace realism_reader_test
}  // namespace parksim
