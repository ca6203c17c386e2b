// Episodes from Python: parksim.run() (the whole of `parksim run`), parksim.Episode (the step
// API for users' own controllers) and parksim.DynamicsWorld (the bare simulation, for the
// reinforcement-learning environment).

#include <optional>

#include <pybind11/stl.h>

#include "app/PlanOutput.h"
#include "parksim/core/Error.h"
#include "parksim/core/Provenance.h"
#include "parksim/renders/EpisodeFrames.h"
#include "parksim/sim/DynamicsWorld.h"
#include "parksim/sim/EpisodeFiles.h"
#include "python/src/Bindings.h"
#include "python/src/Conversions.h"

namespace parksim::python {

namespace {

struct RunOutcome {
  std::shared_ptr<const Scenario> scenario;
  std::optional<PlanOutcome> plan;
  Trajectory trajectory;
  EpisodeResult episode;
  nlohmann::json metrics;
  std::optional<RecordingResult> recording;
  bool ran = false;
  bool realism = false;  // executed.csv has the realism columns
};

RunOutcome runWorld(const World& world, const py::object& plan, const py::object& film,
                    py::dict& options) {
  RunOutcome out;
  out.scenario = world.scenario;
  const Scenario& scenario = *world.scenario;
  std::optional<PlanSetup> setup;
  if (plan.is_none()) setup = planSetupFrom(options);
  const ExecutionDef exec = executionFrom(world, options);
  rejectUnknownOptions(options, "run");
  out.realism = exec.realism.active();
  std::optional<FrameDef> frame_def;
  if (!film.is_none()) frame_def = defFrom<FrameDef>(film, "film");

  nlohmann::json plan_summary;
  if (setup) {
    out.plan = planWorld(world, *setup);
    if (!out.plan->result.solved()) return out;
    out.trajectory = out.plan->result.trajectory;
    plan_summary = app::planSummary(scenario, *setup, out.plan->result);
  } else {
    out.trajectory = trajectoryFrom(plan);
    if (out.trajectory.points.empty()) throw Error("run: the plan has no points");
    plan_summary = app::trajectorySummary(scenario, out.trajectory);
  }

  py::gil_scoped_release release;
  std::unique_ptr<FrameRecorder> recorder;
  EpisodeObserver observer;
  double period = 1.0 / 30.0;
  if (frame_def) {
    recorder = std::make_unique<FrameRecorder>(scenario, *frame_def);
    recorder->setPlan(out.trajectory);
    observer = [&recorder](const EpisodeSample& s) { recorder->addFrame(frameInput(s)); };
    period = 1.0 / frame_def->fps;
  }
  // The same call as `parksim run`.
  out.episode = runEpisode(scenario, out.trajectory, exec, observer, period);
  if (recorder) out.recording = recorder->finish();
  out.metrics = metricsToJson(out.episode.metrics);
  out.metrics["world"] = scenario.source_path;
  out.metrics["scenario"] = scenario.name;
  app::addPlanKeys(out.metrics, plan_summary);
  const nlohmann::json provenance = provenanceToJson(buildProvenance());
  for (const auto& [key, value] : provenance.items()) {
    out.metrics["provenance." + key] = value;
  }
  out.ran = true;
  return out;
}

// parksim.Episode: an Episode with its inputs kept, and a wheel command held until changed.
struct EpisodeHandle {
  std::shared_ptr<const Scenario> scenario;
  Trajectory plan;
  std::unique_ptr<Episode> episode;
  std::optional<WheelSpeeds> held;  // unset: the tracking controller drives
  bool realism = false;

  EpisodeHandle(const World& w, Trajectory p, const ExecutionDef& def, const SimModelDef& model)
      : scenario(w.scenario),
        plan(std::move(p)),
        episode(std::make_unique<Episode>(*scenario, plan, def, model)),
        realism(def.realism.active()) {}

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

ExecutionDef executionFrom(const World& world, py::dict& options) {
  ExecutionDef def;
  if (world.realism->has_realism) def.realism = world.realism->realism;
  def.noise_seed = 1;  // --noise-seed's default
  return takeOptions(def, options);
}

void bindEpisode(py::module_& m) {
  py::class_<RunOutcome>(m, "RunResult", "An episode run by parksim.run().")
      .def_property_readonly(
          "plan",
          [](const RunOutcome& r) -> py::object {
            if (!r.plan) return py::none();
            return py::cast(*r.plan);
          },
          "The PlanResult when run() planned; None when a plan was given.")
      .def_property_readonly(
          "solved", [](const RunOutcome& r) { return r.ran; },
          "False when planning failed (then nothing ran: executed is empty, metrics {}).")
      .def_property_readonly(
          "trajectory",
          [](const RunOutcome& r) { return trajectoryArray(r.trajectory, r.scenario->robot); },
          "The plan driven, as trajectory.csv.")
      .def_property_readonly(
          "executed", [](const RunOutcome& r) { return executedArray(r.episode.rows, r.realism); },
          "Structured array with executed.csv's columns.")
      .def_property_readonly(
          "metrics",
          [](const RunOutcome& r) { return r.ran ? toPython(r.metrics) : py::object(py::dict()); },
          "metrics.json's content as a dict.")
      .def_property_readonly("contact_events",
                             [](const RunOutcome& r) { return contactEvents(r.episode.metrics); })
      .def_property_readonly("recording", [](const RunOutcome& r) -> py::object {
        if (!r.recording) return py::none();
        py::dict d;
        d["frames"] = r.recording->frames;
        d["frames_dir"] = r.recording->frames_dir;
        d["video"] = r.recording->video.path;
        d["gif"] = r.recording->gif.path;
        d["message"] = r.recording->message;
        return d;
      });

  m.def(
      "run",
      [](const World& world, const py::object& plan, const py::object& film,
         const py::kwargs& kwargs) {
        py::dict options = optionsDict(kwargs);
        return runWorld(world, plan, film, options);
      },
      py::arg("world"), py::arg("plan") = py::none(), py::arg("film") = py::none(),
      R"(Plans (unless plan is given) and drives the plan in the simulation, as `parksim run`.

plan: None (plan with plan()'s options: planner, seed, steering, smooth, ...), a PlanResult,
  a structured array like PlanResult.trajectory, or a trajectory.csv path.
Execution options: any ExecutionDef field (tracking="closed" or "open", gains={...}, ...).
film: None, or a FrameDef / dict of its fields (out_dir, fps, video, ...) to write frames.
Results are bit-identical to `parksim run` for the same options.
Releases the GIL while planning and simulating.)");

  py::class_<EpisodeHandle>(
      m, "Episode",
      "An episode stepped from Python: the plan is the reference the episode is measured "
      "against; the tracking controller drives unless set_wheel_speeds() holds a command.")
      .def(py::init([](const World& world, const py::object& plan, const py::object& model,
                       const py::kwargs& kwargs) {
             py::dict options = optionsDict(kwargs);
             const ExecutionDef exec = executionFrom(world, options);
             rejectUnknownOptions(options, "Episode");
             const SimModelDef sim_model =
                 model.is_none() ? SimModelDef{} : defFrom<SimModelDef>(model, "model");
             return std::make_unique<EpisodeHandle>(world, trajectoryFrom(plan), exec, sim_model);
           }),
           py::arg("world"), py::arg("plan"), py::arg("model") = py::none(),
           "Options: any ExecutionDef field (tracking, gains, ...).")
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

  py::class_<DynamicsHandle>(m, "DynamicsWorld",
                             "The bare simulation: the world's obstacles and the robot, driven by "
                             "wheel motor targets. No plan, no measurement (see Episode).")
      .def(py::init([](const World& world, const py::object& start, const py::object& model) {
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

}  // namespace parksim::python
