// parksim.RobotDef: the robot (core/model/RobotDef.h), a differential drive or a car, with the
// world file's checks. Each field is checked when it is set (its sign and its range,
// PhysicalRanges.h, the reader's own), and the whole robot when it is made and by check()
// (checkRobot, scenario/world/RobotSection.h: the reader's checks that join several keys), so
// no limit is written twice. A field of the other drive is refused by name, as in a file.

#include <cmath>
#include <optional>
#include <string>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/scenario/world/PhysicalRanges.h"
#include "parksim/scenario/world/RobotSection.h"
#include "python/src/Bindings.h"

namespace parksim::python {

namespace {

enum class Owner { kBoth, kDifferential, kCar };

// One property: a RobotDef member, shown times `view` (degrees for radians), checked as the
// world file's `range_key` in the file's unit, `to_file` times the member's (no key: the sign
// alone, zero allowed).
struct RobotField {
  const char* name;
  double RobotDef::*member;
  Owner owner;
  const char* range_key;
  double view;
  double to_file;
  bool in_dict;  ///< to_dict() and pickling write it (the degree views are not written)
  const char* doc;
};

constexpr double kDeg = 180.0 / kPi;

const RobotField kFields[] = {
    {"length_m", &RobotDef::length_m, Owner::kBoth, "robot.length", 1.0, 1.0, true,
     "Footprint length along the heading, m."},
    {"width_m", &RobotDef::width_m, Owner::kBoth, "robot.width", 1.0, 1.0, true,
     "Footprint width across the heading, m."},
    {"front_overhang_m", &RobotDef::front_overhang_m, Owner::kBoth, nullptr, 1.0, 1.0, true,
     "From the reference point (the fixed axle's middle) forward to the front edge, m."},
    {"wheel_base_m", &RobotDef::wheel_base_m, Owner::kDifferential, "robot.wheel_base", 1.0, 1.0,
     true, "Between the wheels' contact points, m (a car's: track_m)."},
    {"track_m", &RobotDef::wheel_base_m, Owner::kCar, "robot.track", 1.0, 1.0, true,
     "A car's rear wheels' track: between their contact points, m."},
    {"wheel_radius_m", &RobotDef::wheel_radius_m, Owner::kBoth, "robot.wheel_radius", 1.0, 1.0,
     true, "Wheel radius, m."},
    {"max_wheel_speed_radps", &RobotDef::max_wheel_speed_radps, Owner::kDifferential,
     "robot.max_wheel_speed_radps", 1.0, 1.0, true,
     "Largest wheel speed, rad/s (a car's follows from its own limits: read-only)."},
    {"max_wheel_accel_radps2", &RobotDef::max_wheel_accel_radps2, Owner::kDifferential,
     "robot.max_wheel_accel_radps2", 1.0, 1.0, true,
     "Largest wheel acceleration, rad/s^2 (a car's follows from its own limits: read-only)."},
    {"height_m", &RobotDef::height_m, Owner::kBoth, "robot.height", 1.0, 1.0, true,
     "Body height, m."},
    {"ground_clearance_m", &RobotDef::ground_clearance_m, Owner::kBoth, nullptr, 1.0, 1.0, true,
     "The chassis' underside above the ground, m."},
    {"axle_distance_m", &RobotDef::axle_distance_m, Owner::kCar, "robot.axle_distance", 1.0, 1.0,
     true, "A car's rear axle to front axle, m."},
    {"max_steer_rad", &RobotDef::max_steer_rad, Owner::kCar, "robot.max_steer_deg", 1.0, kDeg, true,
     "A car's largest front-wheel angle (bicycle model), rad."},
    {"max_steer_deg", &RobotDef::max_steer_rad, Owner::kCar, "robot.max_steer_deg", kDeg, kDeg,
     false, "max_steer_rad in degrees (the world file's key)."},
    {"max_steer_rate_radps", &RobotDef::max_steer_rate_radps, Owner::kCar,
     "robot.max_steer_rate_degps", 1.0, kDeg, true, "A car's largest steering rate, rad/s."},
    {"max_steer_rate_degps", &RobotDef::max_steer_rate_radps, Owner::kCar,
     "robot.max_steer_rate_degps", kDeg, kDeg, false,
     "max_steer_rate_radps in degrees/s (the world file's key)."},
    {"max_speed_mps", &RobotDef::max_speed_mps, Owner::kCar, "robot.max_speed_mps", 1.0, 1.0, true,
     "A car's largest speed, forward or reverse, m/s."},
    {"max_accel_mps2", &RobotDef::max_accel_mps2, Owner::kCar, "robot.max_accel_mps2", 1.0, 1.0,
     true, "A car's largest acceleration along its heading, m/s^2."},
};

bool owns(const RobotDef& r, Owner owner) {
  return owner == Owner::kBoth || (owner == Owner::kCar) == r.isCar();
}

const char* driveName(const RobotDef& r) { return r.isCar() ? "car" : "differential"; }

// The drive's defaults, as a world file's robot.drive starts from them.
RobotDef robotOfDrive(const std::string& drive) {
  if (drive == "car") return midSizeCar();
  if (drive == "differential") return RobotDef{};
  throw py::value_error("RobotDef.drive: unknown drive \"" + drive +
                        "\"; expected one of: differential, car");
}

// Sets one field from its property's value as the world reader reads its key: the sign, then
// the range.
void setField(RobotDef& r, const RobotField& f, double value) {
  const std::string where = std::string("RobotDef.") + f.name + ": ";
  if (!owns(r, f.owner)) {
    throw py::value_error(
        where + (r.isCar()
                     ? "a differential drive's field: a car's wheel limits follow from its own "
                       "(track_m, axle_distance_m, max_speed_mps, max_accel_mps2; docs/cars.md)"
                     : "a car's field: this robot is a differential drive (RobotDef(drive=\"car\") "
                       "makes a car, docs/cars.md)"));
  }
  const double member = value / f.view;
  const double in_file = member * f.to_file;
  std::string shown = formatGeneral(value, 17);
  if (in_file != value) shown += " (" + formatGeneral(in_file, 6) + " in the file's unit)";
  const bool zero_allowed = f.range_key == nullptr;
  if (!std::isfinite(value) || (zero_allowed ? value < 0.0 : value <= 0.0)) {
    throw py::value_error(where + (zero_allowed ? "must be non-negative" : "must be positive") +
                          ", got " + shown);
  }
  if (f.range_key) {
    if (const std::optional<std::string> problem =
            rangeProblem(physicalRange(f.range_key), in_file, shown)) {
      throw py::value_error(where + *problem);
    }
  }
  r.*f.member = member;
  if (r.isCar()) setCarWheelLimits(r);
}

// A robot from options: `drive` first (it picks the defaults), then each field; then the
// whole robot as the reader checks it.
RobotDef robotFrom(py::dict options) {
  RobotDef robot;
  if (options.contains("drive")) {
    robot = robotOfDrive(py::str(options["drive"]));
    PyDict_DelItem(options.ptr(), py::str("drive").ptr());
  }
  for (const RobotField& f : kFields) {
    if (!options.contains(f.name)) continue;
    setField(robot, f, options[f.name].cast<double>());
    PyDict_DelItem(options.ptr(), py::str(f.name).ptr());
  }
  rejectUnknownOptions(options, "RobotDef");
  checkRobot(robot);
  return robot;
}

py::dict robotDict(const RobotDef& r) {
  py::dict d;
  d["drive"] = driveName(r);
  for (const RobotField& f : kFields) {
    if (f.in_dict && owns(r, f.owner)) d[f.name] = r.*f.member;
  }
  return d;
}

}  // namespace

void bindRobot(py::module_& m) {
  py::class_<RobotDef> c(
      m, "RobotDef",
      "The robot (core/model/RobotDef.h), SI units: a differential drive (the default, the "
      "study's robot) or a car (drive=\"car\": the mid-size car, docs/cars.md). "
      "RobotDef(drive=..., **fields) starts from the drive's defaults; each field set is checked "
      "as the world file's key (sign and range), and the robot as a whole when made and by "
      "check() (the reader's checks that join keys). Errors are ValueError with the reader's "
      "message.");
  c.def(py::init([](const py::kwargs& kwargs) { return robotFrom(optionsDict(kwargs)); }),
        "The drive's defaults, with the given fields changed.");
  c.def(py::init([](const py::dict& fields) { return robotFrom(py::dict(fields)); }),
        "The drive's defaults, with the dict's fields changed.");
  c.def_property(
      "drive", [](const RobotDef& r) { return std::string(driveName(r)); },
      [](RobotDef& r, const std::string& drive) {
        if (drive != driveName(r)) r = robotOfDrive(drive);
      },
      "differential or car; setting the other drive starts from its defaults, as a world "
      "file's robot.drive does.");
  for (const RobotField& f : kFields) {
    c.def_property(
        f.name, [&f](const RobotDef& r) { return r.*f.member * f.view; },
        [&f](RobotDef& r, double value) { setField(r, f, value); }, f.doc);
  }
  c.def_property_readonly("min_turning_radius_m", &RobotDef::minTurningRadius,
                          "A car's tightest turn of the reference point, m.");
  c.def(
      "check", [](const RobotDef& r) { checkRobot(r); },
      "Raises parksim.Error (a ValueError) with the world reader's message when a world file "
      "would refuse this robot (ranges and the checks that join several keys).");
  c.def("to_dict", &robotDict, "drive and the drive's own fields (radians for angles).");
  c.def(
      "to_world",
      [](const RobotDef& r) {
        const py::object float_type = py::module_::import("builtins").attr("float");
        py::dict d;
        for (const RobotSectionKey& k : robotSection(r)) {
          const py::str value(k.value);
          d[k.key.c_str()] = k.key == "drive" ? py::object(value) : float_type(value);
        }
        return d;
      },
      "The world file's robot: section (its keys and units), as load_world(dict) reads it.");
  c.def("__repr__", [](const RobotDef& r) {
    std::string text = "RobotDef(";
    bool first = true;
    for (const auto& [key, value] : robotDict(r)) {
      text += (first ? "" : ", ") + py::str(key).cast<std::string>() + "=" +
              py::repr(value).cast<std::string>();
      first = false;
    }
    return text + ")";
  });
  c.def(py::pickle([](const RobotDef& r) { return robotDict(r); },
                   [](const py::dict& fields) { return robotFrom(py::dict(fields)); }));
  py::implicitly_convertible<py::dict, RobotDef>();
}

}  // namespace parksim::python
