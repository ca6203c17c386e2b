#include "parksim/scenario/world/RealismReader.h"

#include <algorithm>
#include <optional>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/realism/DriveSizing.h"
#include "parksim/scenario/world/RealismSections.h"

namespace parksim {

namespace {

// Key setters: each key present overrides one field of the preset.
struct Section {
  explicit Section(const YamlMap& m) : map(m) {}
  const YamlMap& map;
  void positive(std::string_view key, double& out) const {
    if (const std::optional<YamlField> f = map.optional(key)) out = f->positive();
  }
  void nonNegative(std::string_view key, double& out) const {
    if (const std::optional<YamlField> f = map.optional(key)) out = f->nonNegative();
  }
  void number(std::string_view key, double& out) const {
    if (const std::optional<YamlField> f = map.optional(key)) out = f->number();
  }
  void boolean(std::string_view key, bool& out) const {
    if (const std::optional<YamlField> f = map.optional(key)) out = f->boolean();
  }
  void fraction(std::string_view key, double& out) const {
    if (const std::optional<YamlField> f = map.optional(key)) {
      out = f->nonNegative();
      if (out > 1.0) f->fail("must lie in [0, 1], got " + f->node().Scalar());
    }
  }
};

void readMotor(const YamlField& field, MotorDef& d) {
  const YamlMap m =
      field.map({"enabled", "stall_torque_nm", "no_load_speed_radps", "time_constant_s",
                 "startup_effort", "rolling_resistance", "supply_limit", "gain_mismatch_pct"});
  const Section s(m);
  s.boolean("enabled", d.enabled);
  s.positive("stall_torque_nm", d.stall_torque_nm);
  s.positive("no_load_speed_radps", d.no_load_speed_radps);
  s.positive("time_constant_s", d.time_constant_s);
  s.fraction("startup_effort", d.startup_effort);
  s.nonNegative("rolling_resistance", d.rolling_resistance);
  s.fraction("supply_limit", d.supply_limit);
  s.nonNegative("gain_mismatch_pct", d.gain_mismatch_pct);
}

void readWheelLoop(const YamlField& field, WheelSpeedLoopDef& d) {
  const YamlMap m = field.map({"rate_hz", "kp", "ki"});
  const Section s(m);
  s.positive("rate_hz", d.rate_hz);
  s.nonNegative("kp", d.kp);
  s.nonNegative("ki", d.ki);
}

void readCalibration(const YamlField& field, CalibrationDef& d) {
  const YamlMap m =
      field.map({"left_radius_error_pct", "right_radius_error_pct", "radius_error_range_pct",
                 "track_error_pct", "track_error_range_pct"});
  const Section s(m);
  s.number("left_radius_error_pct", d.left_radius_error_pct);
  s.number("right_radius_error_pct", d.right_radius_error_pct);
  s.nonNegative("radius_error_range_pct", d.radius_error_range_pct);
  s.number("track_error_pct", d.track_error_pct);
  s.nonNegative("track_error_range_pct", d.track_error_range_pct);
}

void readEncoder(const YamlField& field, EncoderDef& d) {
  const YamlMap m = field.map({"counts_per_turn", "noise_counts"});
  const Section s(m);
  s.nonNegative("counts_per_turn", d.counts_per_turn);
  s.nonNegative("noise_counts", d.noise_counts);
}

void readPoseSensor(const YamlField& field, PoseSensorDef& d) {
  const YamlMap m = field.map({"enabled", "rate_hz", "latency_s", "position_noise_m",
                               "heading_noise_deg", "dropout_probability"});
  const Section s(m);
  s.boolean("enabled", d.enabled);
  s.positive("rate_hz", d.rate_hz);
  s.nonNegative("latency_s", d.latency_s);
  s.nonNegative("position_noise_m", d.position_noise_m);
  if (const std::optional<YamlField> f = m.optional("heading_noise_deg")) {
    d.heading_noise_rad = degToRad(f->nonNegative());
  }
  s.fraction("dropout_probability", d.dropout_probability);
}

void readEstimator(const YamlField& field, EstimatorDef& d) {
  const YamlMap m = field.map({"kind", "odometry_variance_per_m", "history_steps"});
  if (const std::optional<YamlField> f = m.optional("kind")) {
    const std::string kind = f->text();
    if (kind != "truth" && kind != "odometry" && kind != "fused") {
      f->fail("unknown estimator \"" + kind + "\"; expected one of: truth, odometry, fused");
    }
    d.kind = estimatorKindFromString(kind);
  }
  Section(m).positive("odometry_variance_per_m", d.odometry_variance_per_m);
  if (const std::optional<YamlField> f = m.optional("history_steps")) {
    d.history_steps = f->positiveInt();
  }
}

void readControl(const YamlField& field, ControlLoopDef& d) {
  const YamlMap m = field.map({"rate_hz", "latency_s", "settle_s"});
  const Section s(m);
  s.nonNegative("rate_hz", d.rate_hz);
  s.nonNegative("latency_s", d.latency_s);
  s.nonNegative("settle_s", d.settle_s);
}

RealismDef readRealism(const YamlField& field, const RobotDef& robot, const PhysicsDef& physics) {
  const YamlMap m = field.map({"preset", "motor", "wheel_loop", "calibration", "encoder",
                               "pose_sensor", "estimator", "control"});
  RealismDef d;
  if (const std::optional<YamlField> f = m.optional("preset")) {
    const std::string name = f->text();
    const std::vector<std::string> presets = realismPresetNames();
    if (std::find(presets.begin(), presets.end(), name) == presets.end()) {
      f->fail("unknown preset \"" + name + "\"; expected one of: " + joinNames(presets));
    }
    d = presetRealismFor(name, robot, physics);
  }
  bool changed = false;
  const auto section = [&](std::string_view key, auto reader, auto& out) {
    if (const std::optional<YamlField> f = m.optional(key)) {
      reader(*f, out);
      changed = true;
    }
  };
  section("motor", readMotor, d.motor);
  section("wheel_loop", readWheelLoop, d.wheel_loop);
  section("calibration", readCalibration, d.calibration);
  section("encoder", readEncoder, d.encoder);
  section("pose_sensor", readPoseSensor, d.pose_sensor);
  section("estimator", readEstimator, d.estimator);
  section("control", readControl, d.control);
  if (changed) d.name = d.name + "+world";
  try {
    validateRealism(d);
  } catch (const Error& e) {
    field.fail(e.what());
  }
  return d;
}

TrackingTolerance readTolerance(const YamlField& field, const RobotDef& robot) {
  const YamlMap m =
      field.map({"max_pos_err_m", "goal_pos_err_m", "goal_heading_err_deg", "max_contacts",
                 "max_parked_displacement_m", "require_goal_reached"});
  TrackingTolerance t = defaultTolerance(robot);
  const Section s(m);
  s.positive("max_pos_err_m", t.max_pos_err_m);
  s.positive("goal_pos_err_m", t.goal_pos_err_m);
  s.positive("goal_heading_err_deg", t.goal_heading_err_deg);
  if (const std::optional<YamlField> f = m.optional("max_contacts")) {
    const double v = f->nonNegative();
    if (v != static_cast<double>(static_cast<int>(v))) f->fail("must be a whole number");
    t.max_contacts = static_cast<int>(v);
  }
  s.nonNegative("max_parked_displacement_m", t.max_parked_displacement_m);
  s.boolean("require_goal_reached", t.require_goal_reached);
  return t;
}

}  // namespace

WorldRealism readRealismSections(const YamlMap& top, const RobotDef& robot,
                                 const PhysicsDef& physics) {
  WorldRealism w;
  w.tolerance = defaultTolerance(robot);
  if (const std::optional<YamlField> f = top.optional("realism")) {
    w.realism = readRealism(*f, robot, physics);
    w.has_realism = true;
  }
  if (const std::optional<YamlField> f = top.optional("tolerance")) {
    w.tolerance = readTolerance(*f, robot);
    w.has_tolerance = true;
  }
  return w;
}

}  // namespace parksim
