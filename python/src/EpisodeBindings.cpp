// Episodes from Python: parksim.run() (the whole of `parksim run`), parksim.Episode (the step
// API for users' own controllers) and parksim.DynamicsWorld (the bare simulation, for the
// reinforcement-learning environment).

#include <optional>

#include <pybind11/stl.h>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/results/episode/MetricsFile.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "python/src/Bindings.h"
#include "python/src/Conversions.h"
#include "python/src/UserCode.h"

namespace parksim::python {

namespace {

struct RunOutcome {
  std::shared_ptr<const Scenario> scenario;
  std::optional<PlanOutcome> plan;
  EpisodeOutcome outcome;
};

py::dict verdictDict(const Verdict& v) {
  py::dict d;
  d["status"] = toString(v.status);
  d["met"] = v.met();
  d["reason"] = v.reason;
  return d;
}

// run()'s plan argument as the request's plan to drive (None: the pipeline plans).
void takePlan(const py::object& plan, EpisodeRequest& request) {
  if (plan.is_none()) return;
  request.given_plan = trajectoryFrom(plan, request.world->scenario.robot);
  if (py::isinstance<py::str>(plan) || py::hasattr(plan, "__fspath__")) {
    request.given_plan_source = py::str(py::module_::import("os").attr("fspath")(plan));
  }
}

RunOutcome runWorld(const WorldHandle& world, const py::object& plan, const py::object& film,
                    const py::object& out, py::dict& options) {
  EpisodeRequest request = requestFrom(world, options, plan.is_none());
  const IsolationOptions isolation = takeIsolation(options);
  rejectUnknownOptions(options, "run");
  takePlan(plan, request);
  const bool isolate = isolation.applyTo(request);
  if (!out.is_none()) {
    request.out_dir = py::str(py::module_::import("os").attr("fspath")(out));
    request.record.files = FilesPolicy::kAll;
  }
  if (!film.is_none()) {
    request.film.when = FilmWhen::kAlways;
    request.film.frames = defFrom<FrameDef>(film, "film");
    if (request.out_dir.empty()) request.out_dir = request.film.frames.out_dir;
  }
  RunOutcome r;
  r.scenario = world.scenario;
  r.outcome = runRequest(request, isolate);
  // The plan, when it was made here or the planner failed (a plan made in a worker whose
  // controller then crashed is lost with it).
  if (!request.given_plan && (r.outcome.plan || !r.outcome.plan_summary.is_null())) {
    r.plan = planOutcomeOf(world.scenario, r.outcome);
  }
  return r;
}

// parksim.Episode: an Episode with its inputs kept, and a wheel command held until changed.
// The settings (execution, tolerance) are the pipeline's for the same options
// (resolveSettings), so a stepped episode drives and is judged as run() would.
struct EpisodeHandle {
  std::shared_ptr<const Scenario> scenario;
  Trajectory plan;
  EpisodeSettings settings;
  std::unique_ptr<Episode> episode;
  std::optional<WheelSpeeds> held;  // unset: the tracking controller drives
  bool realism = false;

  EpisodeHandle(const WorldHandle& w, Trajectory p, EpisodeSettings s, const SimModelDef& model)
      : scenario(w.scenario),
        plan(std::move(p)),
        settings(std::move(s)),
        episode(std::make_unique<Episode>(*scenario, plan, settings.execution, model)),
        realism(settings.execution.realism.active()) {}

  bool step(long n) {
    py::gil_scoped_release release;
    for (long i = 0; i < n && !episode->finished(); ++i) {
      if (held) {
        episode->step(*held);
      } else {
        episode->step();
      }
    }
    return episode->finished();
  }
};

py::dict observation(const EpisodeHandle& h) {
  const Episode& e = *h.episode;
  const RobotState& state = e.world().robot();
  const EpisodeSample sample = e.sample();
  py::dict d;
  d["t"] = sample.tracking.t_s;
  d["pose"] = poseTuple(state.pose);
  // What the controller believes: the true pose for an ideal robot, the estimator's output
  // under a realism (ExecutionDef.realism).
  d["estimated_pose"] = poseTuple(sample.tracking.estimate);
  d["encoders"] = py::make_tuple(sample.tracking.encoder_rad.left_radps,
                                 sample.tracking.encoder_rad.right_radps);
  d["wheel_speeds"] = py::make_tuple(state.wheels.left_radps, state.wheels.right_radps);
  d["twist"] = py::make_tuple(state.twist.v_mps, state.twist.omega_radps);
  d["reference"] = poseTuple(sample.tracking.reference);
  d["wheel_speeds_cmd"] =
      py::make_tuple(sample.tracking.wheels_cmd.left_radps, sample.tracking.wheels_cmd.right_radps);
  d["pos_err"] = sample.tracking.pos_err_m;
  d["heading_err"] = sample.tracking.heading_err_rad;
  d["contacts"] = sample.contacts;
  d["stopping"] = sample.stopping;
  return d;
}

py::list contactEvents(const EpisodeMetrics& m) {
  py::list l;
  for (const ContactEvent& c : m.contact_events) {
    py::dict d;
    d["t"] = c.t_s;
    d["obstacle_index"] = c.obstacle_index;
    d["body"] = c.body;
    l.append(d);
  }
  return l;
}

struct DynamicsHandle {
  std::shared_ptr<const Scenario> scenario;
  std::unique_ptr<DynamicsWorld> world;
};

py::dict robotState(const RobotState& s) {
  py::dict d;
  d["pose"] = poseTuple(s.pose);
  d["twist"] = py::make_tuple(s.twist.v_mps, s.twist.omega_radps);
  d["wheel_speeds"] = py::make_tuple(s.wheels.left_radps, s.wheels.right_radps);
  d["axle_height"] = s.axle_height_m;
  d["tilt"] = s.tilt_rad;
  return d;
}

}  // namespace

EpisodeRequest requestFrom(const WorldHandle& world, py::dict& options, bool planning) {
  EpisodeRequest r;
  r.world = world.world;
  takeComponents(options, r);
  if (planning) r.plan = planSetupFrom(options);
  const auto take = [&options](const char* key) -> py::object {
    if (!options.contains(key)) return py::none();
    return options.attr("pop")(key);
  };
  if (const py::object v = take("controller"); !v.is_none()) {
    if (!py::isinstance<py::str>(v)) throw py::type_error("controller must be a controller's name");
    r.controller = v.cast<std::string>();
  }
  if (const py::object v = take("controller_params"); !v.is_none()) {
    r.controller_params = paramsFrom(v, "controller_params");
  }
  if (const py::object v = take("realism"); !v.is_none()) r.realism = v.cast<std::string>();
  if (const py::object v = take("noise_seed"); !v.is_none()) {
    r.noise_seed = v.cast<std::uint64_t>();
  }
  if (const py::object v = take("realisations"); !v.is_none()) r.realisations = v.cast<int>();
  if (const py::object v = take("min_success_fraction"); !v.is_none()) {
    r.min_success_fraction = v.cast<double>();
  }
  if (const py::object v = take("tolerance"); !v.is_none()) {
    py::dict bounds(v.cast<py::dict>());
    const auto bound = [&bounds](const char* key) -> std::optional<double> {
      if (!bounds.contains(key)) return std::nullopt;
      const double value = bounds.attr("pop")(key).cast<double>();
      return value;
    };
    r.tolerance.max_pos_err_m = bound("max_pos_err_m");
    r.tolerance.goal_pos_err_m = bound("goal_pos_err_m");
    r.tolerance.goal_heading_err_deg = bound("goal_heading_err_deg");
    r.tolerance.max_parked_displacement_m = bound("max_parked_displacement_m");
    if (const std::optional<double> n = bound("max_contacts")) {
      r.tolerance.max_contacts = static_cast<int>(*n);
    }
    rejectUnknownOptions(bounds, "tolerance");
  }
  r.execution = takeOptions(r.execution, options);
  return r;
}

namespace {

void bindRunResult(py::module_& m) {
  py::class_<RunOutcome>(m, "RunResult", "An episode run by parksim.run().")
      .def_property_readonly(
          "plan",
          [](const RunOutcome& r) -> py::object {
            if (!r.plan) return py::none();
            return py::cast(*r.plan);
          },
          "The PlanResult when run() planned (its status planner_error when the planner failed); "
          "None when a plan was given.")
      .def_property_readonly(
          "solved", [](const RunOutcome& r) { return r.outcome.driven(); },
          "False when there was nothing to drive (then executed is empty and metrics holds the "
          "verdict without measurements).")
      .def_property_readonly(
          "status", [](const RunOutcome& r) { return toString(r.outcome.verdict.status); },
          "The verdict: met, plan_failed, plan_invalid, planner_error, controller_error, "
          "contact, goal_missed or tolerance_missed (as the command line's exit status and a "
          "sweep row's status).")
      .def_property_readonly(
          "met", [](const RunOutcome& r) { return r.outcome.verdict.met(); },
          "True when the episode met its tolerance (status == 'met').")
      .def_property_readonly(
          "reason", [](const RunOutcome& r) { return r.outcome.verdict.reason; },
          "The verdict's one line: why the episode failed; empty when met.")
      .def_property_readonly(
          "realisations",
          [](const RunOutcome& r) {
            py::list l;
            for (const RealisationOutcome& x : r.outcome.realisations) {
              py::dict d = verdictDict(x.verdict);
              d["noise_seed"] = x.noise_seed;
              d["metrics"] = toPython(metricsToJson(x.metrics));
              l.append(d);
            }
            return l;
          },
          "One dict per realisation (noise_seed, status, met, reason, metrics).")
      .def_property_readonly(
          "trajectory",
          [](const RunOutcome& r) {
            return trajectoryArray(r.outcome.trajectory, r.scenario->robot);
          },
          "The plan driven, as trajectory.csv.")
      .def_property_readonly(
          "executed",
          [](const RunOutcome& r) {
            return executedArray(r.outcome.episode.rows, r.outcome.execution.realism.active());
          },
          "Structured array with executed.csv's columns.")
      .def_property_readonly(
          "metrics", [](const RunOutcome& r) { return toPython(r.outcome.metrics); },
          "metrics.json's content as a dict: the measurements and the verdict; the verdict, "
          "the plan's keys and the tolerance alone when nothing was driven.")
      .def_property_readonly(
          "files", [](const RunOutcome& r) { return r.outcome.files; },
          "Files written (paths under out), when out was given.")
      .def_property_readonly(
          "contact_events",
          [](const RunOutcome& r) { return contactEvents(r.outcome.episode.metrics); })
      .def_property_readonly("recording", [](const RunOutcome& r) -> py::object {
        if (!r.outcome.recording) return py::none();
        const RecordingResult& rec = *r.outcome.recording;
        py::dict d;
        d["frames"] = rec.frames;
        d["frames_dir"] = rec.frames_dir;
        d["video"] = rec.video.path;
        d["gif"] = rec.gif.path;
        d["message"] = rec.message;
        return d;
      });

  m.def(
      "run",
      [](const WorldHandle& world, const py::object& plan, const py::object& film,
         const py::object& out, const py::kwargs& kwargs) {
        py::dict options = optionsDict(kwargs);
        return runWorld(world, plan, film, out, options);
      },
      py::arg("world"), py::arg("plan") = py::none(), py::arg("film") = py::none(),
      py::arg("out") = py::none(),
      R"(Plans (unless plan is given), drives the plan in the simulation and judges it: the
episode pipeline, as `parksim run`, with the same defaults and the same verdict.

plan: None (plan with plan()'s options: planner, seed, steering, smooth, ...), a PlanResult,
  a structured array like PlanResult.trajectory, or a trajectory.csv path.
Options: realism ("world": the world's realism: section, else ideal; or "ideal", "lab",
  "odometry"), noise_seed=1, realisations=1, min_success_fraction=1.0, tolerance={bound: value}
  (max_pos_err_m, goal_pos_err_m, goal_heading_err_deg, max_contacts,
  max_parked_displacement_m), and any ExecutionDef field (tracking="closed" or "open",
  gains={...}, ...).
film: None, or a FrameDef / dict of its fields (out_dir, fps, video, ...) to write frames.
out: None, or a directory for trajectory.csv, plan.json, executed.csv and metrics.json.
The result's status, met and reason are the verdict. Results are bit-identical to
`parksim run` for the same options. Releases the GIL while planning and simulating.
isolate=True runs the episode in a worker process, as parksim.sweep's workers run: a Python
  object or a plugin that crashes, plans longer than planner_timeout (s, default 600) or takes
  longer than controller_timeout (s, default 10) for one command gives planner_error or
  controller_error instead of ending the interpreter; the result is otherwise the same.
  The timeouts also stop a command planner's or controller's program (without isolate too).)");
}

void bindEpisodeHandle(py::module_& m) {
  py::class_<EpisodeHandle>(
      m, "Episode",
      "An episode stepped from Python: the plan is the reference the episode is measured "
      "against; the tracking controller drives unless set_wheel_speeds() holds a command.")
      .def(py::init([](const WorldHandle& world, const py::object& plan, const py::object& model,
                       const py::kwargs& kwargs) {
             py::dict options = optionsDict(kwargs);
             EpisodeRequest request = requestFrom(world, options, false);
             rejectUnknownOptions(options, "Episode");
             request.given_plan = trajectoryFrom(plan, world.scenario->robot);
             checkEpisodeRequest(request);
             const SimModelDef sim_model =
                 model.is_none() ? SimModelDef{} : defFrom<SimModelDef>(model, "model");
             return std::make_unique<EpisodeHandle>(world, *request.given_plan,
                                                    resolveSettings(request), sim_model);
           }),
           py::arg("world"), py::arg("plan"), py::arg("model") = py::none(),
           "Options as run()'s: realism, noise_seed, tolerance={...} and any ExecutionDef field "
           "(tracking, gains, ...).")
      .def(
          "verdict",
          [](const EpisodeHandle& h) {
            return verdictDict(
                judgeEpisode(*h.scenario, h.settings.tolerance, h.episode->metrics()));
          },
          "The verdict on the steps so far, as run() judges a finished episode: a dict with "
          "status, met and reason.")
      .def("step", &EpisodeHandle::step, py::arg("n") = 1,
           "Advances n simulation steps (fewer if the episode finishes); returns finished. "
           "Releases the GIL.")
      .def(
          "set_wheel_speeds",
          [](EpisodeHandle& h, double left, double right) {
            h.held = WheelSpeeds{left, right};
          },
          py::arg("left"), py::arg("right"),
          "Holds these wheel motor targets (rad/s) for the following steps, instead of the "
          "tracking controller's.")
      .def(
          "use_controller", [](EpisodeHandle& h) { h.held.reset(); },
          "Hands the wheels back to the tracking controller.")
      .def(
          "controller_command",
          [](const EpisodeHandle& h) {
            const WheelSpeeds w = h.episode->controllerCommand();
            return py::make_tuple(w.left_radps, w.right_radps);
          },
          "(left, right) rad/s the tracking controller would command for the next step.")
      .def("observation", &observation,
           "Dict: t, pose (true), estimated_pose (what the controller believes), encoders (wheel "
           "angles as reported, rad), wheel_speeds (measured, rad/s), twist (v, omega), "
           "reference (plan pose now), wheel_speeds_cmd, pos_err, heading_err, contacts "
           "(obstacle indices), stopping.")
      .def_property_readonly(
          "plan", [](const EpisodeHandle& h) { return trajectoryArray(h.plan, h.scenario->robot); },
          "The plan the episode is measured against (structured array).")
      .def_property_readonly("finished",
                             [](const EpisodeHandle& h) { return h.episode->finished(); })
      .def_property_readonly("time",
                             [](const EpisodeHandle& h) { return h.episode->world().time(); })
      .def_property_readonly("steps",
                             [](const EpisodeHandle& h) { return h.episode->world().steps(); })
      .def_property_readonly("time_step",
                             [](const EpisodeHandle& h) { return h.episode->world().timeStep(); })
      .def_property_readonly(
          "contacts", [](const EpisodeHandle& h) { return h.episode->world().chassisContacts(); },
          "Indices of the obstacles the chassis penetrates now.")
      .def_property_readonly(
          "obstacle_poses",
          [](const EpisodeHandle& h) { return posesArray(h.episode->world().obstaclePoses()); },
          "N x 3 array: box centre x, y and yaw of every obstacle now.")
      .def_property_readonly(
          "executed",
          [](const EpisodeHandle& h) { return executedArray(h.episode->rows(), h.realism); },
          "Rows recorded so far (executed.csv's columns).")
      .def_property_readonly(
          "metrics",
          [](const EpisodeHandle& h) { return toPython(metricsToJson(h.episode->metrics())); },
          "metrics.json's episode keys for the steps so far.")
      .def_property_readonly("contact_events", [](const EpisodeHandle& h) {
        return contactEvents(h.episode->metrics());
      });
}

void bindDynamicsWorld(py::module_& m) {
  py::class_<DynamicsHandle>(m, "DynamicsWorld",
                             "The bare simulation: the world's obstacles and the robot, driven by "
                             "wheel motor targets. No plan, no measurement (see Episode).")
      .def(py::init([](const WorldHandle& world, const py::object& start, const py::object& model) {
             const Pose2 pose = start.is_none() ? world.scenario->start : poseFrom(start);
             const SimModelDef sim_model =
                 model.is_none() ? SimModelDef{} : defFrom<SimModelDef>(model, "model");
             return DynamicsHandle{
                 world.scenario, std::make_unique<DynamicsWorld>(*world.scenario, pose, sim_model)};
           }),
           py::arg("world"), py::arg("start") = py::none(), py::arg("model") = py::none())
      .def(
          "set_wheel_targets",
          [](DynamicsHandle& h, double left, double right) {
            h.world->setWheelTargets({left, right});
          },
          py::arg("left"), py::arg("right"), "Wheel motor targets, rad/s, held until changed.")
      .def(
          "step",
          [](DynamicsHandle& h, long n) {
            py::gil_scoped_release release;
            for (long i = 0; i < n; ++i) h.world->step();
          },
          py::arg("n") = 1, "Advances n fixed steps. Releases the GIL.")
      .def_property_readonly("time", [](const DynamicsHandle& h) { return h.world->time(); })
      .def_property_readonly("steps", [](const DynamicsHandle& h) { return h.world->steps(); })
      .def_property_readonly("time_step",
                             [](const DynamicsHandle& h) { return h.world->timeStep(); })
      .def_property_readonly(
          "pose", [](const DynamicsHandle& h) { return poseTuple(h.world->robot().pose); })
      .def(
          "robot_state", [](const DynamicsHandle& h) { return robotState(h.world->robot()); },
          "Dict: pose, twist (v, omega), wheel_speeds, axle_height, tilt.")
      .def_property_readonly("contacts",
                             [](const DynamicsHandle& h) { return h.world->chassisContacts(); })
      .def_property_readonly("obstacle_poses", [](const DynamicsHandle& h) {
        return posesArray(h.world->obstaclePoses());
      });
}

// The episode record's fields (results/EpisodeRecord.h): what run().metrics and a sweep's row
// hold, and under which keys.
void bindEpisodeFields(py::module_& m) {
  m.def(
      "_episode_fields",
      [] {
        static const char* const kGroups[] = {"identity", "parameter",  "outcome",
                                              "plan",     "simulation", "realism",
                                              "timing",   "provenance", "seal"};
        static const char* const kTypes[] = {"string", "boolean", "integer",
                                             "number", "list",    "object"};
        py::list fields;
        for (const EpisodeField& f : episodeFields()) {
          py::dict d;
          d["key"] = std::string(f.key);
          d["metrics_key"] = std::string(f.metrics_key);
          d["group"] = kGroups[static_cast<int>(f.group)];
          d["type"] = kTypes[static_cast<int>(f.type)];
          d["unit"] = std::string(f.unit);
          d["meaning"] = std::string(f.meaning);
          d["read"] = f.read != nullptr;
          d["csv"] = f.csv;
          d["per_name"] = f.per_name;
          fields.append(d);
        }
        return fields;
      },
      "The episode record's fields: key (results table), metrics_key (run().metrics and "
      "metrics.json), group, type, unit, meaning.");
}

}  // namespace

void bindEpisode(py::module_& m) {
  bindEpisodeFields(m);
  bindRunResult(m);
  bindEpisodeHandle(m);
  bindDynamicsWorld(m);
}

}  // namespace parksim::python
