// The ...Def structs as Python classes. Each field is a property, and that is what makes it an
// option: plan(), run(), Episode(), FrameRecorder() take their keyword arguments onto these
// classes with takeOptions (Bindings.h). A field added to a Def is one .def_readwrite here.
// Enumerations are strings, spelled as on the command line.

#include <pybind11/stl.h>

#include "parksim/planner/base/PlanScenario.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/rl/ParkingTaskDef.h"
#include "parksim/sim/episode/ExecutionDef.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "python/src/Bindings.h"

namespace parksim::python {

namespace {

py::list propertyNames(const py::handle& type) {
  const py::object property = py::module_::import("builtins").attr("property");
  py::list names;
  for (const py::handle name : py::module_::import("builtins").attr("dir")(type)) {
    const std::string s = py::str(name);
    if (s[0] != '_' && py::isinstance(type.attr(name), property)) names.append(name);
  }
  return names;
}

// A Def class: Def(**fields) or Def(dict), repr, to_dict(), pickling (as to_dict()), and dicts
// convert implicitly where a Def is expected (nested options such as gains={"k_x": 5}).
template <class Def>
py::class_<Def> defClass(py::module_& m, const char* name, const char* doc) {
  py::class_<Def> c(m, name, doc);
  c.def(py::init([name](const py::kwargs& kwargs) {
          py::dict options = optionsDict(kwargs);
          Def def = takeOptions(Def{}, options);
          rejectUnknownOptions(options, name);
          return def;
        }),
        "Defaults, with the given fields changed.");
  c.def(py::init([name](const py::dict& fields) {
          py::dict options(fields);
          Def def = takeOptions(Def{}, options);
          rejectUnknownOptions(options, name);
          return def;
        }),
        "Defaults, with the dict's fields changed.");
  c.def("to_dict", [](const py::object& self) {
    py::dict d;
    for (const py::handle field : propertyNames(py::type::of(self))) {
      py::object value = self.attr(field);
      d[field] = py::hasattr(value, "to_dict") ? value.attr("to_dict")() : value;
    }
    return d;
  });
  c.def("__repr__", [name](const py::object& self) {
    std::string text = std::string(name) + "(";
    bool first = true;
    for (const py::handle field : propertyNames(py::type::of(self))) {
      text += (first ? "" : ", ") + py::str(field).cast<std::string>() + "=" +
              py::repr(self.attr(field)).cast<std::string>();
      first = false;
    }
    return text + ")";
  });
  c.def(py::pickle([](const py::object& self) { return py::dict(self.attr("to_dict")()); },
                   [name](const py::dict& fields) {
                     py::dict options(fields);
                     Def def = takeOptions(Def{}, options);
                     rejectUnknownOptions(options, name);
                     return def;
                   }));
  py::implicitly_convertible<py::dict, Def>();
  return c;
}

const char* solverName(SolverKernel kernel) {
  switch (kernel) {
    case SolverKernel::kBullet: return "bullet";
    case SolverKernel::kExact: return "exact";
    case SolverKernel::kFast: return "fast";
  }
  return "fast";
}

SolverKernel solverFromName(const std::string& name) {
  if (name == "bullet") return SolverKernel::kBullet;
  if (name == "exact") return SolverKernel::kExact;
  if (name == "fast") return SolverKernel::kFast;
  throw py::value_error("solver must be bullet, exact or fast, got '" + name + "'");
}

void bindPlanningDefs(py::module_& m) {
  defClass<SearchDef>(m, "SearchDef",
                      "What every planner's search is given besides its own parameters "
                      "(planner/base/SearchDef.h): seed, budget, cost weights, smoothing.")
      .def_readwrite("seed", &SearchDef::seed)
      .def_readwrite("max_iterations", &SearchDef::max_iterations)
      .def_readwrite("max_time_s", &SearchDef::max_time_s)
      .def_readwrite("record_tree", &SearchDef::record_tree)
      .def_readwrite("reverse_penalty", &SearchDef::reverse_penalty)
      .def_readwrite("cusp_penalty_m", &SearchDef::cusp_penalty_m)
      .def_readwrite("smooth", &SearchDef::smooth)
      .def_readwrite("smoothing_attempts", &SearchDef::smoothing_attempts);

  defClass<MoveToPoseDef>(m, "MoveToPoseDef",
                          "Move-to-pose steering (planner/steering/MoveToPoseSteering.h).")
      .def_readwrite("k_rho", &MoveToPoseDef::k_rho)
      .def_readwrite("k_alpha", &MoveToPoseDef::k_alpha)
      .def_readwrite("k_beta", &MoveToPoseDef::k_beta)
      .def_readwrite("period_s", &MoveToPoseDef::period_s)
      .def_readwrite("horizon_s", &MoveToPoseDef::horizon_s)
      .def_readwrite("max_duration_s", &MoveToPoseDef::max_duration_s)
      .def_readwrite("position_tolerance_m", &MoveToPoseDef::position_tolerance_m)
      .def_readwrite("heading_tolerance_rad", &MoveToPoseDef::heading_tolerance_rad)
      .def_readwrite("turn_in_place_radius_m", &MoveToPoseDef::turn_in_place_radius_m)
      .def_readwrite("allow_reverse", &MoveToPoseDef::allow_reverse);

  defClass<RotateTranslateRotateDef>(m, "RotateTranslateRotateDef",
                                     "Rotate-translate-rotate steering "
                                     "(planner/steering/RotateTranslateRotateSteering.h).")
      .def_readwrite("period_s", &RotateTranslateRotateDef::period_s)
      .def_readwrite("horizon_s", &RotateTranslateRotateDef::horizon_s)
      .def_readwrite("speed_fraction", &RotateTranslateRotateDef::speed_fraction)
      .def_readwrite("accel_fraction", &RotateTranslateRotateDef::accel_fraction);

  defClass<MotionValidatorDef>(m, "MotionValidatorDef",
                               "Motion validation (planner/motion/MotionValidator.h).")
      .def_readwrite("resolution_m", &MotionValidatorDef::resolution_m);

  defClass<ReedsSheppDef>(m, "ReedsSheppDef",
                          "Reeds-Shepp steering (planner/steering/ReedsSheppSteering.h).")
      .def_readwrite("turning_radius_m", &ReedsSheppDef::turning_radius_m)
      .def_readwrite("period_s", &ReedsSheppDef::period_s)
      .def_readwrite("horizon_s", &ReedsSheppDef::horizon_s)
      .def_readwrite("speed_fraction", &ReedsSheppDef::speed_fraction);

  // plan()'s options besides SearchDef's: `steering` is the kind, as on the command line.
  defClass<PlanSetup>(m, "PlanSetup",
                      "Everything planScenario takes (planner/base/PlanScenario.h).")
      .def_readwrite("planner", &PlanSetup::planner)
      .def_readwrite("planner_params", &PlanSetup::planner_params)
      .def_readwrite("search", &PlanSetup::search)
      .def_property(
          "steering", [](const PlanSetup& s) { return std::string(toString(s.steering_kind)); },
          [](PlanSetup& s, const std::string& name) {
            s.steering_kind = steeringKindFromString(name);
          })
      .def_readwrite("move_to_pose", &PlanSetup::steering)
      .def_readwrite("goal_tolerance_fraction", &PlanSetup::goal_tolerance_fraction)
      .def_readwrite("rotate_translate_rotate", &PlanSetup::rotate_translate_rotate)
      .def_readwrite("validation", &PlanSetup::validation)
      .def_readwrite("reeds_shepp", &PlanSetup::reeds_shepp)
      .def_property(
          "timing", [](const PlanSetup& s) { return std::string(toString(s.timing)); },
          [](PlanSetup& s, const std::string& name) { s.timing = timingKindFromString(name); })
      .def_readwrite("feedback_headroom", &PlanSetup::feedback_headroom);
}

void bindEpisodeDefs(py::module_& m) {
  defClass<ExecutionDef>(m, "ExecutionDef",
                         "How an episode drives a plan (sim/episode/ExecutionDef.h).")
      .def_property(
          "tracking", [](const ExecutionDef& d) { return std::string(toString(d.tracking)); },
          [](ExecutionDef& d, const std::string& s) { d.tracking = trackingModeFromString(s); })
      .def_readwrite("rest_speed_mps", &ExecutionDef::rest_speed_mps)
      .def_readwrite("rest_yaw_rate_radps", &ExecutionDef::rest_yaw_rate_radps)
      .def_readwrite("rest_hold_s", &ExecutionDef::rest_hold_s)
      .def_readwrite("max_stop_time_s", &ExecutionDef::max_stop_time_s)
      .def_readwrite("contact_merge_s", &ExecutionDef::contact_merge_s)
      .def_readwrite("csv_stride_steps", &ExecutionDef::csv_stride_steps)
      // A preset name, as --realism (the world's realism: section applies when none is given).
      .def_property(
          "realism", [](const ExecutionDef& d) { return d.realism.name; },
          [](ExecutionDef& d, const std::string& preset) { d.realism = presetRealism(preset); })
      .def_readwrite("noise_seed", &ExecutionDef::noise_seed);

  defClass<SimModelDef>(m, "SimModelDef",
                        "Simulation model parts the world file does not describe "
                        "(sim/world/DynamicsWorld.h).")
      .def_readwrite("support_radius_m", &SimModelDef::support_radius_m)
      .def_readwrite("support_inset_m", &SimModelDef::support_inset_m)
      .def_readwrite("support_deflection_m", &SimModelDef::support_deflection_m)
      .def_readwrite("support_mass_kg", &SimModelDef::support_mass_kg)
      .def_readwrite("parked_wake_distance_m", &SimModelDef::parked_wake_distance_m)
      .def_readwrite("parked_sleep_speed_mps", &SimModelDef::parked_sleep_speed_mps)
      .def_readwrite("parked_sleep_yaw_rate_radps", &SimModelDef::parked_sleep_yaw_rate_radps)
      .def_readwrite("wheel_contact_processing_m", &SimModelDef::wheel_contact_processing_m)
      .def_property(
          "solver", [](const SimModelDef& d) { return std::string(solverName(d.solver)); },
          [](SimModelDef& d, const std::string& s) { d.solver = solverFromName(s); })
      .def_readwrite("solver_residual_threshold", &SimModelDef::solver_residual_threshold)
      .def_readwrite("ground_margin_m", &SimModelDef::ground_margin_m)
      .def_readwrite("local_frame_grid_m", &SimModelDef::local_frame_grid_m);

  defClass<FrameDef>(m, "FrameDef", "Filming an episode (renders/film/FrameRecorder.h).")
      .def_readwrite("fps", &FrameDef::fps)
      .def_readwrite("width_px", &FrameDef::width_px)
      .def_readwrite("height_px", &FrameDef::height_px)
      .def_property(
          "view", [](const FrameDef& d) { return std::string(toString(d.view)); },
          [](FrameDef& d, const std::string& s) { d.view = frameViewFromString(s); })
      .def_property(
          "png_compression",
          [](const FrameDef& d) { return std::string(toString(d.png_compression)); },
          [](FrameDef& d, const std::string& s) {
            d.png_compression = pngCompressionFromString(s);
          })
      .def_readwrite("out_dir", &FrameDef::out_dir)
      .def_readwrite("video", &FrameDef::video)
      .def_readwrite("gif", &FrameDef::gif)
      .def_readwrite("ffmpeg", &FrameDef::ffmpeg)
      .def_readwrite("show_tree", &FrameDef::show_tree)
      .def_readwrite("msaa_samples", &FrameDef::msaa_samples)
      .def_readwrite("encode_threads", &FrameDef::encode_threads)
      .def_readwrite("queue_depth", &FrameDef::queue_depth)
      .def_readwrite("frame_memory_bytes", &FrameDef::frame_memory_bytes)
      .def_property(
          "gl_backend", [](const FrameDef& d) { return std::string(toString(d.context.backend)); },
          [](FrameDef& d, const std::string& s) {
            d.context.backend = contextBackendFromString(s);
          },
          "auto (PARKSIM_GL_BACKEND, else egl, then osmesa), egl or osmesa");
}

void bindTaskDefs(py::module_& m) {
  defClass<ParkingTaskDef>(m, "ParkingTaskDef",
                           "The reinforcement-learning parking task (rl/ParkingTaskDef.h): "
                           "ParkingEnv's and VecParkingEnv's options.")
      .def_property(
          "fidelity", [](const ParkingTaskDef& d) { return std::string(toString(d.fidelity)); },
          [](ParkingTaskDef& d, const std::string& s) { d.fidelity = taskFidelityFromString(s); },
          "dynamics (Bullet, realism) or kinematic (exact arcs against the collision checker, "
          "for pre-training)")
      .def_readwrite("control_period_s", &ParkingTaskDef::control_period_s)
      .def_readwrite("max_episode_steps", &ParkingTaskDef::max_episode_steps)
      .def_readwrite("start_position_noise_m", &ParkingTaskDef::start_position_noise_m)
      .def_readwrite("start_heading_noise_rad", &ParkingTaskDef::start_heading_noise_rad)
      .def_readwrite("success_position_m", &ParkingTaskDef::success_position_m)
      .def_readwrite("success_heading_rad", &ParkingTaskDef::success_heading_rad)
      .def_readwrite("distance_scale_m", &ParkingTaskDef::distance_scale_m)
      .def_readwrite("heading_weight", &ParkingTaskDef::heading_weight)
      .def_readwrite("discount", &ParkingTaskDef::discount)
      .def_readwrite("shaping_weight", &ParkingTaskDef::shaping_weight)
      .def_readwrite("success_reward", &ParkingTaskDef::success_reward)
      .def_readwrite("contact_reward", &ParkingTaskDef::contact_reward)
      .def_readwrite("exit_reward", &ParkingTaskDef::exit_reward)
      .def_readwrite("terminate_on_contact", &ParkingTaskDef::terminate_on_contact)
      .def_readwrite("model", &ParkingTaskDef::model)
      .def_readwrite("kinematic_check_m", &ParkingTaskDef::kinematic_check_m);
}

}  // namespace

void bindDefs(py::module_& m) {
  bindPlanningDefs(m);
  bindEpisodeDefs(m);
  bindTaskDefs(m);
}

}  // namespace parksim::python
