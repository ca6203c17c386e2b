// Conversions between core types and Python objects: poses, JSON, structured arrays.

#include <cstddef>
#include <string>

#include <pybind11/stl.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/params/ParamSet.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "python/src/Bindings.h"
#include "python/src/Conversions.h"

namespace parksim::python {

namespace {

// One row of each structured array; field names are the CSV files' column names.
struct TrajectoryRecord {
  double t, x, y, theta, omega_left, omega_right, v, omega;
};
struct ExecutedRecord {
  double t, x, y, theta, x_ref, y_ref, theta_ref, omega_left_cmd, omega_right_cmd, omega_left,
      omega_right, pos_err, heading_err;
};

// Under a realism, executed.csv's extra columns too.
struct ExecutedRealismRecord {
  double t, x, y, theta, x_ref, y_ref, theta_ref, omega_left_cmd, omega_right_cmd, omega_left,
      omega_right, pos_err, heading_err, x_est, y_est, theta_est, est_pos_err, est_heading_err,
      effort_left, effort_right, torque_left, torque_right, slip_left, slip_right, encoder_left,
      encoder_right;
};

void registerDtypes() {
  static const bool done = [] {
    PYBIND11_NUMPY_DTYPE(TrajectoryRecord, t, x, y, theta, omega_left, omega_right, v, omega);
    PYBIND11_NUMPY_DTYPE(ExecutedRecord, t, x, y, theta, x_ref, y_ref, theta_ref, omega_left_cmd,
                         omega_right_cmd, omega_left, omega_right, pos_err, heading_err);
    PYBIND11_NUMPY_DTYPE(ExecutedRealismRecord, t, x, y, theta, x_ref, y_ref, theta_ref,
                         omega_left_cmd, omega_right_cmd, omega_left, omega_right, pos_err,
                         heading_err, x_est, y_est, theta_est, est_pos_err, est_heading_err,
                         effort_left, effort_right, torque_left, torque_right, slip_left,
                         slip_right, encoder_left, encoder_right);
    return true;
  }();
  (void)done;
}

}  // namespace

py::array posesArray(const std::vector<Pose2>& poses) {
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{3}});
  auto r = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    r(k, 0) = poses[i].x;
    r(k, 1) = poses[i].y;
    r(k, 2) = poses[i].theta;
  }
  return out;
}

void rejectUnknownOptions(const py::dict& options, const std::string& function) {
  if (options.empty()) return;
  std::string names;
  for (const auto& item : options) {
    names += (names.empty() ? "" : ", ") + py::str(item.first).cast<std::string>();
  }
  throw py::type_error(function + ": unknown option" + (options.size() == 1 ? " " : "s ") + names);
}

py::dict optionsDict(const py::kwargs& kwargs) { return py::dict(kwargs); }

Pose2 poseFrom(const py::handle& sequence) {
  const auto values = py::cast<std::vector<double>>(sequence);
  if (values.size() != 3) throw py::value_error("a pose is (x, y, theta): three numbers");
  return {values[0], values[1], values[2]};
}

py::tuple poseTuple(const Pose2& pose) { return py::make_tuple(pose.x, pose.y, pose.theta); }

py::object toPython(const nlohmann::json& json) {
  switch (json.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& [key, value] : json.items()) d[py::str(key)] = toPython(value);
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& value : json) l.append(toPython(value));
      return l;
    }
    case nlohmann::json::value_t::string: return py::str(json.get<std::string>());
    case nlohmann::json::value_t::boolean: return py::bool_(json.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(json.get<long long>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(json.get<unsigned long long>());
    case nlohmann::json::value_t::number_float: return py::float_(json.get<double>());
    default: return py::none();
  }
}

py::array trajectoryArray(const Trajectory& trajectory, const RobotDef& robot) {
  registerDtypes();
  py::array_t<TrajectoryRecord> out(static_cast<py::ssize_t>(trajectory.points.size()));
  TrajectoryRecord* r = out.mutable_data();
  for (const TrajectoryPoint& p : trajectory.points) {
    // The same twist trajectory.csv's v and omega columns hold.
    const Twist tw = toTwist(p.wheels, robot);
    *r++ = {
        p.t_s,    p.pose.x,      p.pose.y, p.pose.theta, p.wheels.left_radps, p.wheels.right_radps,
        tw.v_mps, tw.omega_radps};
  }
  return out;
}

Trajectory trajectoryFrom(const py::handle& plan, const RobotDef& robot) {
  if (py::isinstance<PlanOutcome>(plan)) {
    const PlanOutcome& outcome = plan.cast<const PlanOutcome&>();
    if (!outcome.verdict.met()) {
      throw Error("the plan may not be driven (" + outcome.status() + "): " + outcome.message());
    }
    return outcome.result->trajectory;
  }
  if (py::isinstance<py::str>(plan) || py::hasattr(plan, "__fspath__")) {
    return readTrajectoryCsv(py::str(py::module_::import("os").attr("fspath")(plan)), robot);
  }
  const py::array array = py::array::ensure(plan);
  if (!array || array.dtype().attr("names").is_none() || array.ndim() != 1) {
    throw py::type_error(
        "a plan is a PlanResult, a trajectory.csv path or a structured array with fields t, x, "
        "y, theta, omega_left, omega_right");
  }
  auto column = [&](const char* name) {
    return py::array_t<double, py::array::forcecast>(plan[py::str(name)]);
  };
  const auto t = column("t"), x = column("x"), y = column("y"), theta = column("theta"),
             left = column("omega_left"), right = column("omega_right");
  Trajectory traj;
  const auto n = static_cast<std::size_t>(array.shape(0));
  traj.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    traj.points[i] = {t.at(k), {x.at(k), y.at(k), theta.at(k)}, {left.at(k), right.at(k)}};
  }
  return traj;
}

namespace {

// Columns and values as executedCsv writes them (results/ExecutedFile.h): the ones every episode
// has.
template <typename Record>
void fillExecuted(Record& r, const ExecutedRow& row) {
  r.t = row.t_s;
  r.x = row.pose.x;
  r.y = row.pose.y;
  r.theta = row.pose.theta;
  r.x_ref = row.reference.x;
  r.y_ref = row.reference.y;
  r.theta_ref = row.reference.theta;
  r.omega_left_cmd = row.wheels_cmd.left_radps;
  r.omega_right_cmd = row.wheels_cmd.right_radps;
  r.omega_left = row.wheels.left_radps;
  r.omega_right = row.wheels.right_radps;
  r.pos_err = row.pos_err_m;
  r.heading_err = row.heading_err_rad;
}

}  // namespace

py::array executedArray(const std::vector<ExecutedRow>& rows, bool realism_columns) {
  registerDtypes();
  if (!realism_columns) {
    py::array_t<ExecutedRecord> out(static_cast<py::ssize_t>(rows.size()));
    ExecutedRecord* r = out.mutable_data();
    for (const ExecutedRow& row : rows) fillExecuted(*r++, row);
    return out;
  }
  py::array_t<ExecutedRealismRecord> out(static_cast<py::ssize_t>(rows.size()));
  ExecutedRealismRecord* r = out.mutable_data();
  for (const ExecutedRow& row : rows) {
    fillExecuted(*r, row);
    r->x_est = row.estimate.x;
    r->y_est = row.estimate.y;
    r->theta_est = row.estimate.theta;
    r->est_pos_err = row.est_pos_err_m;
    r->est_heading_err = row.est_heading_err_rad;
    r->effort_left = row.effort.left_radps;
    r->effort_right = row.effort.right_radps;
    r->torque_left = row.torque_nm.left_radps;
    r->torque_right = row.torque_nm.right_radps;
    r->slip_left = row.slip_mps.left_radps;
    r->slip_right = row.slip_mps.right_radps;
    r->encoder_left = row.encoder_rad.left_radps;
    r->encoder_right = row.encoder_rad.right_radps;
    ++r;
  }
  return out;
}

ParamMap paramsFrom(const py::handle& dict, const char* what) {
  if (!py::isinstance<py::dict>(dict)) {
    throw py::type_error(std::string(what) + " must be a dict of parameter names to values");
  }
  ParamMap params;
  for (const auto& [key, value] : dict.cast<py::dict>()) {
    if (!py::isinstance<py::str>(key)) throw py::type_error(std::string(what) + ": names are str");
    std::string text;
    if (py::isinstance<py::bool_>(value)) {
      text = value.cast<bool>() ? "true" : "false";
    } else if (py::isinstance<py::int_>(value)) {
      text = std::to_string(value.cast<long long>());
    } else if (py::isinstance<py::float_>(value)) {
      text = formatShortest(value.cast<double>());
    } else if (py::isinstance<py::str>(value)) {
      text = canonicalParamText(value.cast<std::string>());
    } else {
      throw py::type_error(std::string(what) + "[" + key.cast<std::string>() +
                           "]: a bool, int, float or str, not " +
                           std::string(py::str(value.get_type().attr("__name__"))));
    }
    params[key.cast<std::string>()] = text;
  }
  return params;
}

}  // namespace parksim::python
