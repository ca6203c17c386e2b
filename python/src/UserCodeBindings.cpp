// Python objects as parksim planners and controllers (docs/your-code.md): plan(planner=obj) and
// run(planner=..., controller=...) register them for that call beside parksim's own and the
// plugins' (usercode/Components.h), as untrusted user code: their plans are checked before they
// are driven, and what they raise or get wrong is a planner_error or controller_error.
//
//   class Straight:                      # a planner: solve(problem) -> trajectory or None
//       def solve(self, problem):
//           traj, reached = problem.steer(problem.start, problem.goal)
//           return traj if reached and problem.is_valid(traj) else None
//
//   def hold(obs):                       # a controller: a callable, or reset()/command()
//       return obs.feedforward

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "parksim/core/io/Error.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/base/Planner.h"
#include "parksim/rl/TaskSpaces.h"
#include "parksim/sim/control/Controller.h"
#include "parksim/usercode/PluginLoader.h"
#include "python/src/Bindings.h"
#include "python/src/Conversions.h"
#include "python/src/UserCode.h"

namespace parksim::python {

namespace {

// A Python object held by C++ code that runs without the GIL: copied and released with it.
struct Held {
  explicit Held(py::object o) : object(std::move(o)) {}
  ~Held() {
    py::gil_scoped_acquire gil;
    object = py::object();
  }
  py::object object;
};

// Python's exception as a one-line C++ one, made while the GIL is held (a pybind11
// error_already_set needs the GIL to be read or destroyed).
[[noreturn]] void rethrowAsUserCodeFailure(py::error_already_set& e) {
  std::string text = e.what();
  const std::size_t newline = text.find('\n');
  if (newline != std::string::npos) text.resize(newline);
  e.restore();
  PyErr_Clear();
  throw std::runtime_error(text);
}

// The problem a Python planner sees, valid during its solve() call.
struct PyProblem {
  const PlanningProblem* p = nullptr;
};

class PyPlanner : public Planner {
 public:
  explicit PyPlanner(std::shared_ptr<Held> planner) : planner_(std::move(planner)) {}

  PlanResult solve(const PlanningProblem& problem) override {
    py::gil_scoped_acquire gil;
    PlanResult r;
    try {
      const py::object answer = planner_->object.attr("solve")(PyProblem{&problem});
      if (answer.is_none()) {
        r.status = PlanStatus::kIterationLimit;
        r.message = "the planner found no plan";
        return r;
      }
      // Only an array: a str is not read as a trajectory.csv path, as plan= of run() reads one.
      if (!py::isinstance<py::array>(answer)) {
        throw std::runtime_error(
            "solve() returned a " +
            std::string(py::str(py::type::of(answer).attr("__qualname__"))) +
            ", not a trajectory (a structured array with fields t, x, y, theta, omega_left, "
            "omega_right) or None");
      }
      r.trajectory = trajectoryFrom(answer);
    } catch (py::error_already_set& e) {
      rethrowAsUserCodeFailure(e);
    }
    r.status = PlanStatus::kSolved;
    r.message = "solved";
    return r;
  }

 private:
  std::shared_ptr<Held> planner_;
};

class PyController : public Controller {
 public:
  explicit PyController(std::shared_ptr<Held> controller) : controller_(std::move(controller)) {}

  void reset(const ControllerSetup& setup) override {
    py::gil_scoped_acquire gil;
    robot_ = setup.scenario.robot;
    try {
      const py::object& c = controller_->object;
      callable_ = !py::hasattr(c, "command");
      if (!callable_ && py::hasattr(c, "reset")) {
        py::dict s;
        s["plan"] = trajectoryArray(setup.plan, setup.scenario.robot);
        s["robot"] = setup.scenario.robot;
        s["period_s"] = setup.period_s;
        s["latency_s"] = setup.latency_s;
        s["estimated_pose"] = setup.estimated_pose;
        s["ideal_robot"] = setup.ideal_robot;
        s["goal"] = poseTuple(setup.scenario.goal.pose);
        const LotBounds& lot = setup.scenario.lot;
        s["lot"] = py::make_tuple(lot.x_min_m, lot.y_min_m, lot.x_max_m, lot.y_max_m);
        c.attr("reset")(s);
      }
    } catch (py::error_already_set& e) {
      rethrowAsUserCodeFailure(e);
    }
  }

  WheelSpeeds command(const ControllerInput& in) override {
    py::gil_scoped_acquire gil;
    try {
      const py::object& c = controller_->object;
      const py::object out = callable_ ? c(py::cast(in)) : c.attr("command")(py::cast(in));
      return wheelsFrom(out);
    } catch (py::error_already_set& e) {
      rethrowAsUserCodeFailure(e);
    } catch (const py::cast_error&) {
      throw std::runtime_error("returned something that is not two numbers (left, right)");
    }
  }

  // A car: a parksim.CarCommand, or two wheel speeds read as its rear wheels'.
  std::optional<CarCommand> carCommand(const ControllerInput& in) override {
    py::gil_scoped_acquire gil;
    try {
      const py::object& c = controller_->object;
      const py::object out = callable_ ? c(py::cast(in)) : c.attr("command")(py::cast(in));
      if (py::isinstance<CarCommand>(out)) return out.cast<CarCommand>();
      return carCommandOfWheels(wheelsFrom(out), robot_, in.steer_rad);
    } catch (py::error_already_set& e) {
      rethrowAsUserCodeFailure(e);
    } catch (const py::cast_error&) {
      throw std::runtime_error(
          "returned something that is not a parksim.CarCommand or two numbers (left, right)");
    }
  }

 private:
  static WheelSpeeds wheelsFrom(const py::handle& out) {
    // A tuple, list or array of two real numbers; strings and complex numbers are not.
    const py::sequence s = out.cast<py::sequence>();
    if (py::isinstance<py::str>(out) || s.size() != 2) {
      throw std::runtime_error("returned something that is not two numbers (left, right)");
    }
    auto number = [](const py::handle& v) {
      // Real numbers only: not str or bytes (float() would parse them), not complex.
      if (PyComplex_Check(v.ptr()) || py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v) ||
          !py::hasattr(v, "__float__")) {
        throw std::runtime_error("returned something that is not two real numbers (left, right)");
      }
      return py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
    };
    return {number(s[0]), number(s[1])};
  }

  std::shared_ptr<Held> controller_;
  bool callable_ = true;
  RobotDef robot_;
};

// A policy trained on the parking task (ParkingEnv: rl/TaskSpaces.h's observation and action)
// as a controller: every period_s it builds the task's observation as the task does (the pose
// the controller may use; the true twist of the ideal robot, else the mean speed its encoders
// saw over the last action; the goal), asks the policy for an action and holds the wheel
// speeds that action commands until the next.
class PolicyController {
 public:
  PolicyController(py::object policy, double period_s)
      : policy_(std::move(policy)), period_s_(period_s) {
    if (!PyCallable_Check(policy_.ptr())) {
      throw py::type_error("a policy is a callable: observation -> action");
    }
    if (!(period_s > 0.0 && period_s <= 60.0)) {
      throw py::value_error("period_s must be in (0, 60]");
    }
  }

  void reset(const py::dict& setup) {
    scenario_ = Scenario{};
    scenario_.robot = setup["robot"].cast<RobotDef>();
    const auto lot = setup["lot"].cast<std::tuple<double, double, double, double>>();
    scenario_.lot = {std::get<0>(lot), std::get<1>(lot), std::get<2>(lot), std::get<3>(lot)};
    scenario_.goal.pose = poseFrom(setup["goal"]);
    bounds_ = taskObservationBounds(scenario_, period_s_);
    ideal_ = setup["ideal_robot"].cast<bool>();
    next_t_ = 0.0;
    held_ = {};
    last_t_ = 0.0;
    last_encoders_ = {};
  }

  WheelSpeeds command(const ControllerInput& in) {
    if (in.t_s + 1e-9 < next_t_) return held_;
    next_t_ += period_s_ * std::ceil((in.t_s + 1e-9 - next_t_) / period_s_);
    if (next_t_ <= in.t_s) next_t_ += period_s_;
    // The task's twist (rl/DynamicDrive.cpp): the truth, or the encoders' mean over the action.
    Twist twist = in.twist;
    if (!ideal_) {
      const double elapsed = in.t_s - last_t_;
      twist = {};
      if (elapsed > 0.0) {
        twist = toTwist({(in.encoders_rad.left_radps - last_encoders_.left_radps) / elapsed,
                         (in.encoders_rad.right_radps - last_encoders_.right_radps) / elapsed},
                        scenario_.robot);
      }
      last_t_ = in.t_s;
      last_encoders_ = in.encoders_rad;
    }
    const TaskObservation obs = taskObservation(in.pose, twist, scenario_.goal.pose, bounds_);
    py::array_t<float> array(static_cast<py::ssize_t>(obs.size()));
    std::copy(obs.begin(), obs.end(), array.mutable_data());
    const py::object action = policy_(array);
    const py::array_t<double, py::array::forcecast> a(action);
    if (a.size() != 2) throw std::runtime_error(std::string("action: ") + kTaskActionExpected);
    const TaskAction act{a.at(0), a.at(1)};
    checkTaskAction(act);
    held_ = taskWheelSpeeds(act, scenario_.robot);
    return held_;
  }

 private:
  py::object policy_;
  double period_s_;
  Scenario scenario_;
  TaskObservationBounds bounds_;
  bool ideal_ = true;
  double next_t_ = 0.0;
  WheelSpeeds held_;
  double last_t_ = 0.0;
  WheelSpeeds last_encoders_;
};

std::string componentName(const py::handle& obj, const char* what) {
  std::string name;
  if (py::hasattr(obj, "name") && py::isinstance<py::str>(obj.attr("name"))) {
    name = obj.attr("name").cast<std::string>();
  } else if (py::hasattr(obj, "__name__") && py::isinstance<py::str>(obj.attr("__name__"))) {
    name = obj.attr("__name__").cast<std::string>();
  } else {
    name = py::str(py::type::of(obj).attr("__name__"));
  }
  if (name == "<lambda>") name = "lambda";
  if (!isComponentName(name)) {
    throw py::value_error(std::string("a ") + what + "'s name ('" + name +
                          "': its `name` attribute, else its __name__ or class name) must be 1 to "
                          "64 letters, digits, '-', '_' or '.'");
  }
  return name;
}

// "Python object MODULE.QUALNAME" of a function, a class or (by its class) an instance: where
// results say the code came from.
std::string pythonOrigin(const py::object& object) {
  const py::object of = py::hasattr(object, "__qualname__") ? object : py::type::of(object);
  const std::string module = py::str(py::getattr(of, "__module__", py::str("?")));
  return "Python object " + module + "." + std::string(py::str(of.attr("__qualname__")));
}

}  // namespace

void takeComponents(py::dict& options, EpisodeRequest& request) {
  const auto take = [&options](const char* key) -> py::object {
    if (!options.contains(key)) return py::none();
    return options.attr("pop")(key);
  };
  const py::object plugins = take("plugins");
  const py::object planner =
      options.contains("planner") && !py::isinstance<py::str>(options["planner"])
          ? take("planner")
          : py::object(py::none());
  const py::object controller =
      options.contains("controller") && !py::isinstance<py::str>(options["controller"])
          ? take("controller")
          : py::object(py::none());
  if (plugins.is_none() && planner.is_none() && controller.is_none()) return;
  std::vector<std::string> paths;
  if (!plugins.is_none()) {
    for (const py::handle& p : plugins.cast<py::sequence>()) {
      paths.push_back(py::str(py::module_::import("os").attr("fspath")(p)));
    }
  }
  auto components = std::make_shared<Components>(*loadComponents(paths));
  if (!planner.is_none()) options["planner"] = addPythonPlanner(*components, planner);
  if (!controller.is_none()) options["controller"] = addPythonController(*components, controller);
  request.components = std::move(components);
}

std::string addPythonPlanner(Components& components, const py::object& planner,
                             const std::string& name) {
  if (!name.empty() && !isComponentName(name)) {
    throw py::value_error("planner name '" + name +
                          "' must be 1 to 64 letters, digits, '-', '_' or '.'");
  }
  if (!py::hasattr(planner, "solve")) {
    throw py::type_error("a planner is a name (str) or an object with solve(problem)");
  }
  PlannerEntry entry;
  entry.info.name = name.empty() ? componentName(planner, "planner") : name;
  entry.info.description = "a Python object";
  entry.info.origin = pythonOrigin(planner);
  entry.info.runs_user_code = true;
  entry.info.uses_steering = true;
  auto held = std::make_shared<Held>(planner);
  entry.make = [held](const ParamMap& params) -> std::unique_ptr<Planner> {
    if (!params.empty())
      throw Error("a Python planner takes no planner_params: set its attributes");
    return std::make_unique<PyPlanner>(held);
  };
  const std::string registered = entry.info.name;
  components.planners.add(std::move(entry));
  return registered;
}

std::string addPythonController(Components& components, const py::object& controller,
                                const std::string& name) {
  if (!name.empty() && !isComponentName(name)) {
    throw py::value_error("controller name '" + name +
                          "' must be 1 to 64 letters, digits, '-', '_' or '.'");
  }
  if (!PyCallable_Check(controller.ptr()) && !py::hasattr(controller, "command")) {
    throw py::type_error(
        "a controller is a name (str), a callable (observation) -> (left, right), or an object "
        "with command(observation) and optionally reset(setup)");
  }
  ControllerEntry entry;
  entry.info.name = name.empty() ? componentName(controller, "controller") : name;
  entry.info.description = "a Python object";
  entry.info.runs_user_code = true;
  auto held = std::make_shared<Held>(controller);
  entry.make = [held](const ParamMap& params) -> std::unique_ptr<Controller> {
    if (!params.empty()) {
      throw Error("a Python controller takes no controller_params: set its attributes");
    }
    return std::make_unique<PyController>(held);
  };
  const std::string registered = entry.info.name;
  components.controllers.add(std::move(entry));
  return registered;
}

void bindUserCode(py::module_& m) {
  py::class_<PolicyController>(
      m, "PolicyController",
      "A policy trained on the parking task (ParkingEnv's observation -> action) as a "
      "controller for run(): every period_s it observes as the task does and holds the wheel "
      "speeds of the action. name: 'policy'.")
      .def(py::init<py::object, double>(), py::arg("policy"), py::arg("period_s") = 0.1)
      .def_property_readonly("name", [](const PolicyController&) { return "policy"; })
      .def("reset", &PolicyController::reset, py::arg("setup"))
      .def(
          "command",
          [](PolicyController& c, const ControllerInput& in) {
            const WheelSpeeds w = c.command(in);
            return py::make_tuple(w.left_radps, w.right_radps);
          },
          py::arg("observation"));

  // Field names are ControllerInput's own, unit suffix included (docs/your-code.md's table);
  // the names of before (t, encoders, ...) still read, with a DeprecationWarning.
  py::class_<ControllerInput> input(
      m, "ControllerInput",
      "What a controller knows at one control tick (sim/control/Controller.h).");
  input.def_readonly("tick", &ControllerInput::tick)
      .def_readonly("t_s", &ControllerInput::t_s, "episode time, s")
      .def_property_readonly(
          "pose", [](const ControllerInput& in) { return poseTuple(in.pose); },
          "(x, y, theta): the true pose, or the estimate under a realism; m, rad")
      .def_property_readonly(
          "encoders_rad",
          [](const ControllerInput& in) {
            return py::make_tuple(in.encoders_rad.left_radps, in.encoders_rad.right_radps);
          },
          "the encoders' wheel angles (left, right), rad")
      .def_property_readonly(
          "wheel_speeds_radps",
          [](const ControllerInput& in) {
            return py::make_tuple(in.wheel_speeds_radps.left_radps,
                                  in.wheel_speeds_radps.right_radps);
          },
          "measured wheel speeds (left, right), rad/s")
      .def_property_readonly(
          "twist",
          [](const ControllerInput& in) {
            return py::make_tuple(in.twist.v_mps, in.twist.omega_radps);
          },
          "(v, omega): the true twist (ideal robot), else that of the measured wheel speeds")
      .def_property_readonly(
          "reference", [](const ControllerInput& in) { return poseTuple(in.reference); },
          "the plan's pose at t_s")
      .def_property_readonly(
          "reference_twist",
          [](const ControllerInput& in) {
            return py::make_tuple(in.reference_twist.v_mps, in.reference_twist.omega_radps);
          },
          "the plan's (v, omega) over the interval the command acts, m/s, rad/s")
      .def_property_readonly(
          "feedforward",
          [](const ControllerInput& in) {
            return py::make_tuple(in.feedforward.left_radps, in.feedforward.right_radps);
          },
          "the plan's wheel speeds (left, right) over that interval, rad/s")
      .def_readonly("plan_ended", &ControllerInput::plan_ended)
      .def_readonly("steer_rad", &ControllerInput::steer_rad,
                    "a car's measured steering angle (bicycle model), rad; 0 otherwise")
      .def_readonly("reference_steer_rad", &ControllerInput::reference_steer_rad,
                    "a car's feed-forward steering angle from the plan, rad; 0 otherwise")
      .def_readonly("commanded_speed_mps", &ControllerInput::commanded_speed_mps,
                    "a car's speed commanded at the last tick, m/s");
  for (const auto& [old_name, name] : std::vector<std::pair<const char*, const char*>>{
           {"t", "t_s"},
           {"encoders", "encoders_rad"},
           {"wheel_speeds", "wheel_speeds_radps"},
           {"steer", "steer_rad"},
           {"reference_steer", "reference_steer_rad"},
           {"commanded_speed", "commanded_speed_mps"}}) {
    const std::string message = std::string("ControllerInput.") + old_name +
                                " is deprecated: read ." + name + " (the same value)";
    const std::string field = name;
    input.def_property_readonly(
        old_name,
        [message, field](const py::object& self) {
          if (PyErr_WarnEx(PyExc_DeprecationWarning, message.c_str(), 1) != 0) {
            throw py::error_already_set();
          }
          return self.attr(field.c_str());
        },
        "deprecated: the same value under its unit-suffixed name");
  }

  py::class_<CarCommand>(m, "CarCommand",
                         "A car's command (sim/Controller.h): a speed of its rear axle's middle "
                         "(or an acceleration) and a steering angle. A controller of a car may "
                         "return one instead of two wheel speeds.")
      .def(py::init([](std::optional<double> speed, std::optional<double> accel, double steer) {
             if (speed.has_value() == accel.has_value()) {
               throw py::value_error("give one of speed (m/s) or accel (m/s^2)");
             }
             CarCommand c;
             c.mode = speed ? CarCommand::Mode::kSpeed : CarCommand::Mode::kAcceleration;
             c.speed_mps = speed.value_or(0.0);
             c.accel_mps2 = accel.value_or(0.0);
             c.steer_rad = steer;
             return c;
           }),
           py::kw_only(), py::arg("speed") = py::none(), py::arg("accel") = py::none(),
           py::arg("steer") = 0.0)
      .def_property_readonly("speed",
                             [](const CarCommand& c) -> py::object {
                               if (c.mode != CarCommand::Mode::kSpeed) return py::none();
                               return py::float_(c.speed_mps);
                             })
      .def_property_readonly("accel",
                             [](const CarCommand& c) -> py::object {
                               if (c.mode != CarCommand::Mode::kAcceleration) return py::none();
                               return py::float_(c.accel_mps2);
                             })
      .def_readonly("steer", &CarCommand::steer_rad);

  py::class_<PyProblem>(m, "PlanningProblem",
                        "What a Python planner's solve() is given (planner/base/Planner.h); valid "
                        "during that call.")
      .def_property_readonly("start",
                             [](const PyProblem& p) { return poseTuple(p.p->scenario.start); })
      .def_property_readonly("goal",
                             [](const PyProblem& p) { return poseTuple(p.p->scenario.goal.pose); })
      .def_property_readonly(
          "goal_tolerance",
          [](const PyProblem& p) {
            const GoalRegion& g = p.p->scenario.goal;
            return py::make_tuple(g.position_tolerance_m, g.heading_tolerance_rad,
                                  g.either_heading);
          },
          "(position m, heading rad, either heading)")
      .def_property_readonly("robot", [](const PyProblem& p) { return p.p->scenario.robot; })
      .def_property_readonly("lot",
                             [](const PyProblem& p) {
                               const LotBounds& l = p.p->scenario.lot;
                               return py::make_tuple(l.x_min_m, l.y_min_m, l.x_max_m, l.y_max_m);
                             })
      .def_property_readonly("seed", [](const PyProblem& p) { return p.p->search().seed; })
      .def_property_readonly("max_iterations",
                             [](const PyProblem& p) { return p.p->search().max_iterations; })
      .def_property_readonly("max_time_s",
                             [](const PyProblem& p) { return p.p->search().max_time_s; })
      .def(
          "is_free",
          [](const PyProblem& p, const py::handle& pose, double margin_m) {
            return p.p->checker.isFree(poseFrom(pose), margin_m);
          },
          py::arg("pose"), py::arg("margin_m") = 0.0,
          "Whether the footprint at (x, y, theta), grown by margin_m, overlaps no obstacle.")
      .def(
          "is_valid",
          [](const PyProblem& p, const py::handle& trajectory) {
            return p.p->validator.isValid(trajectoryFrom(trajectory));
          },
          py::arg("trajectory"),
          "The motion check parksim's planners use: the swept footprint free, without gaps, "
          "and inside the lot.")
      .def(
          "steer",
          [](const PyProblem& p, const py::handle& from, const py::handle& to,
             const std::string& mode) {
            const SteerMode m = mode == "exact"     ? SteerMode::kExact
                                : mode == "to_goal" ? SteerMode::kToGoal
                                : mode == "horizon" ? SteerMode::kFixedHorizon
                                                    : throw Error(
                                                          "steer: mode is exact, to_goal "
                                                          "or horizon, got '" +
                                                          mode + "'");
            const SteerResult r = p.p->steering.steer(poseFrom(from), {}, poseFrom(to), m);
            return py::make_tuple(trajectoryArray(r.trajectory, p.p->scenario.robot), r.reached);
          },
          py::arg("from_pose"), py::arg("to_pose"), py::arg("mode") = "exact",
          "The setup's steering function from rest at from_pose toward to_pose: (trajectory, "
          "reached).");
}

}  // namespace parksim::python
