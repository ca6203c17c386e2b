#include "parksim/scenario/world/RobotReader.h"

#include <optional>
#include <string>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/scenario/world/PhysicalRanges.h"

namespace parksim {

namespace {

// The keys only one drive has: the other's file refuses them by name, not as unknown fields.
constexpr std::string_view kCarOnlyKeys[] = {"axle_distance", "track",
                                             "max_steer_deg", "max_steer_rate_degps",
                                             "max_speed_mps", "max_accel_mps2"};
constexpr std::string_view kDifferentialOnlyKeys[] = {"wheel_base", "max_wheel_speed_radps",
                                                      "max_wheel_accel_radps2"};

Drive readDrive(const YamlField& field) {
  const std::string drive = field.text();
  if (drive == "differential") return Drive::kDifferential;
  if (drive == "car") return Drive::kCar;
  field.fail("unknown drive \"" + drive + "\"; expected one of: differential, car");
}

// Sets `out` from `key` when the file gives it, range-checked as robot.<key>.
void setRanged(const YamlMap& m, std::string_view key, double& out) {
  if (const std::optional<YamlField> f = m.optional(key)) {
    out = rangedValue(*f, "robot." + std::string(key));
  }
}

// The chassis' underside must stay below its top.
void readGroundClearance(const YamlMap& m, RobotDef& robot) {
  if (const std::optional<YamlField> f = m.optional("ground_clearance")) {
    robot.ground_clearance_m = f->nonNegative();
    if (!(robot.ground_clearance_m < robot.height_m)) {
      f->fail("must be below robot.height (" + formatNumber(robot.height_m) + "), got " +
              f->node().Scalar());
    }
  } else if (!(robot.ground_clearance_m < robot.height_m)) {
    m.required("height").fail("must be above robot.ground_clearance (" +
                              formatNumber(robot.ground_clearance_m) + "), got " +
                              m.required("height").node().Scalar());
  }
}

// The planner checks the body's footprint only, and the simulated wheels touch only the
// ground: a wheel beyond the body's sides would drive through obstacles unseen. `key` is the
// drive's name for the distance between the wheels (wheel_base, a car's track).
void checkWheelsWithinWidth(const YamlMap& m, const RobotDef& robot, std::string_view key) {
  if (!(robot.wheel_base_m > robot.width_m)) return;
  const std::string why = " (the wheels must lie within the body, which alone meets obstacles)";
  if (const std::optional<YamlField> base = m.optional(key)) {
    base->fail("must not exceed robot.width (" + formatNumber(robot.width_m) + ")" + why +
               ", got " + base->node().Scalar());
  }
  const YamlField width = m.required("width");
  width.fail("must be at least robot." + std::string(key) + " (" +
             formatNumber(robot.wheel_base_m) + ")" + why + ", got " + width.node().Scalar());
}

// Zero is a real design (axle at the front edge); beyond the length the reference point
// would lie outside the body it steers.
void readFrontOverhang(const YamlMap& m, RobotDef& robot) {
  const std::optional<YamlField> overhang = m.optional("front_overhang");
  if (overhang) robot.front_overhang_m = overhang->nonNegative();
  if (robot.front_overhang_m > robot.length_m) {
    if (overhang) {
      overhang->fail("must not exceed robot.length (" + formatNumber(robot.length_m) + "), got " +
                     overhang->node().Scalar());
    }
    const YamlField length = m.required("length");
    length.fail("must be at least robot.front_overhang (" + formatNumber(robot.front_overhang_m) +
                "), got " + length.node().Scalar());
  }
}

// The first of `keys` the map gives, else nothing.
template <std::size_t N>
std::optional<YamlField> firstGiven(const YamlMap& m, const std::string_view (&keys)[N]) {
  for (const std::string_view key : keys) {
    if (std::optional<YamlField> f = m.optional(key)) return f;
  }
  return std::nullopt;
}

RobotDef readDifferential(const YamlField& field) {
  if (const std::optional<YamlField> f = firstGiven(YamlMap(field), kCarOnlyKeys)) {
    f->fail(
        "a car's key: this robot is a differential drive (robot.drive: car makes a car, "
        "docs/cars.md)");
  }
  const YamlMap m =
      field.map({"drive", "length", "width", "front_overhang", "wheel_base", "wheel_radius",
                 "max_wheel_speed_radps", "max_wheel_accel_radps2", "height", "ground_clearance"});
  RobotDef robot;
  // Each key overrides one field; absent keys keep the study's robot.
  setRanged(m, "length", robot.length_m);
  setRanged(m, "width", robot.width_m);
  setRanged(m, "wheel_base", robot.wheel_base_m);
  setRanged(m, "wheel_radius", robot.wheel_radius_m);
  setRanged(m, "max_wheel_speed_radps", robot.max_wheel_speed_radps);
  setRanged(m, "max_wheel_accel_radps2", robot.max_wheel_accel_radps2);
  setRanged(m, "height", robot.height_m);
  readGroundClearance(m, robot);
  checkWheelsWithinWidth(m, robot, "wheel_base");
  readFrontOverhang(m, robot);
  return robot;
}

// A value in degrees, range-checked as robot.<key>, in radians.
void setDegrees(const YamlMap& m, std::string_view key, double& out_rad) {
  if (const std::optional<YamlField> f = m.optional(key)) {
    out_rad = degToRad(rangedValue(*f, "robot." + std::string(key)));
  }
}

RobotDef readCar(const YamlField& field) {
  if (const std::optional<YamlField> f = firstGiven(YamlMap(field), kDifferentialOnlyKeys)) {
    f->fail(
        "a differential drive's key: a car (robot.drive: car) has track (between its rear "
        "wheels), axle_distance (rear axle to front axle), max_speed_mps and max_accel_mps2; its "
        "wheels' limits follow from them (docs/cars.md)");
  }
  const YamlMap m = field.map({"drive", "length", "width", "front_overhang", "axle_distance",
                               "track", "wheel_radius", "max_steer_deg", "max_steer_rate_degps",
                               "max_speed_mps", "max_accel_mps2", "height", "ground_clearance"});
  // Each key overrides one field of the mid-size car.
  RobotDef car = midSizeCar();
  setRanged(m, "length", car.length_m);
  setRanged(m, "width", car.width_m);
  setRanged(m, "axle_distance", car.axle_distance_m);
  setRanged(m, "track", car.wheel_base_m);
  setRanged(m, "wheel_radius", car.wheel_radius_m);
  setDegrees(m, "max_steer_deg", car.max_steer_rad);
  setDegrees(m, "max_steer_rate_degps", car.max_steer_rate_radps);
  setRanged(m, "max_speed_mps", car.max_speed_mps);
  setRanged(m, "max_accel_mps2", car.max_accel_mps2);
  setRanged(m, "height", car.height_m);
  readGroundClearance(m, car);
  checkWheelsWithinWidth(m, car, "track");
  readFrontOverhang(m, car);

  // The front wheels steer inside the body, which alone meets obstacles: the front axle lies
  // no further ahead of the rear axle's middle than the front edge.
  if (car.axle_distance_m > car.front_overhang_m) {
    const std::string why = " (the front axle must lie within the body)";
    if (const std::optional<YamlField> f = m.optional("axle_distance")) {
      f->fail("must not exceed robot.front_overhang (" + formatNumber(car.front_overhang_m) + ")" +
              why + ", got " + f->node().Scalar());
    }
    const YamlField overhang = m.required("front_overhang");
    overhang.fail("must be at least robot.axle_distance (" + formatNumber(car.axle_distance_m) +
                  ")" + why + ", got " + overhang.node().Scalar());
  }
  // Turning tighter than half the track would put the turn's centre between the rear wheels:
  // the inner one would roll backwards while the car drives forwards, which no car does.
  const double radius = car.minTurningRadius();
  if (radius < 0.5 * car.wheel_base_m) {
    std::optional<YamlField> at = m.optional("max_steer_deg");
    if (!at) at = m.optional("axle_distance");
    if (!at) at = m.optional("track");
    const std::string what = "the tightest turning radius, axle_distance / tan(max_steer) = " +
                             formatGeneral(radius, 4) + " m, is smaller than half the track (" +
                             formatGeneral(0.5 * car.wheel_base_m, 4) +
                             " m): the inner rear wheel would roll backwards; lower "
                             "robot.max_steer_deg or lengthen robot.axle_distance, got ";
    (at ? *at : m.required("drive")).fail(what + (at ? at->node().Scalar() : "the defaults"));
  }
  setCarWheelLimits(car);
  return car;
}

}  // namespace

double rangedValue(const YamlField& f, std::string_view key, bool zero_allowed) {
  const double v = zero_allowed ? f.nonNegative() : f.positive();
  if (const std::optional<std::string> problem =
          rangeProblem(physicalRange(key), v, f.node().Scalar())) {
    f.fail(*problem);
  }
  return v;
}

RobotDef readRobot(const YamlField& field) {
  const YamlMap any(field);
  const std::optional<YamlField> drive = any.optional("drive");
  if (drive && readDrive(*drive) == Drive::kCar) return readCar(field);
  return readDifferential(field);
}

}  // namespace parksim
