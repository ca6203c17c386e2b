// parksim.plan() and its result: the episode pipeline without driving, as `parksim plan`.
// Options map onto PlanSetup and SearchDef (DefBindings.cpp); the statistics are plan.json's
// (results/PlanFile.h), so the two never drift apart.

#include <pybind11/stl.h>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "python/src/Bindings.h"
#include "python/src/Conversions.h"
#include "python/src/UserCode.h"

namespace parksim::python {

PlanSetup planSetupFrom(py::dict& options) {
  PlanSetup setup;
  // `planner` names a registered planner, as --planner does.
  if (options.contains("planner")) {
    const py::object value = options.attr("pop")("planner");
    if (!py::isinstance<py::str>(value)) {
      throw py::type_error("planner must be a planner's name (a str)");
    }
    setup.planner = value.cast<std::string>();
  }
  if (options.contains("planner_params")) {
    setup.planner_params = paramsFrom(options.attr("pop")("planner_params"), "planner_params");
  }
  setup = takeOptions(setup, options);
  setup.search = takeOptions(setup.search, options);
  return setup;
}

std::string PlanOutcome::status() const {
  return result ? toString(result->status) : toString(verdict.status);
}

std::string PlanOutcome::message() const { return result ? result->message : verdict.reason; }

PlanOutcome planOutcomeOf(const std::shared_ptr<const Scenario>& scenario,
                          const EpisodeOutcome& outcome) {
  // A solved plan's verdict is met, whatever its drive's; otherwise the plan is why the
  // episode stopped, and the episode's verdict is the plan's.
  const bool solved = outcome.plan && outcome.plan->solved();
  return {scenario, outcome.plan_setup, outcome.plan, outcome.plan_summary,
          solved ? Verdict{} : outcome.verdict};
}

PlanOutcome planWorld(const WorldHandle& world, const EpisodeRequest& request, bool isolate) {
  EpisodeRequest plan_only = request;
  plan_only.drive = false;
  return planOutcomeOf(world.scenario, runRequest(plan_only, isolate));
}

void bindPlan(py::module_& m) {
  py::class_<PlanOutcome>(m, "PlanResult", "A plan: status, trajectory and statistics.")
      .def_property_readonly(
          "solved", [](const PlanOutcome& p) { return p.verdict.met(); },
          "True when the plan may be driven: solved and, when parksim did not make it, checked.")
      .def_property_readonly(
          "status", &PlanOutcome::status,
          "The planner's status (solved, iteration_limit, time_limit, invalid_start, "
          "invalid_goal, cancelled), plan_invalid when a plan parksim did not make failed its "
          "check, or planner_error when a user's planner failed.")
      .def_property_readonly("message", &PlanOutcome::message,
                             "One line: the planner's message, or why the plan failed.")
      .def_property_readonly(
          "verdict",
          [](const PlanOutcome& p) {
            py::dict d;
            d["status"] = toString(p.verdict.status);
            d["met"] = p.verdict.met();
            d["reason"] = p.verdict.reason;
            return d;
          },
          "The pipeline's verdict on the plan, as run()'s: status (met, plan_failed, "
          "plan_invalid, planner_error), met, reason.")
      .def_property_readonly(
          "trajectory",
          [](const PlanOutcome& p) {
            return trajectoryArray(p.result ? p.result->trajectory : Trajectory{},
                                   p.scenario->robot);
          },
          "Structured array with trajectory.csv's columns t, x, y, theta, omega_left, "
          "omega_right, v, omega (s, m, rad, rad/s, m/s); empty unless solved or plan_invalid "
          "(then the plan that failed its check).")
      .def_property_readonly(
          "stats", [](const PlanOutcome& p) { return toPython(p.summary); },
          "plan.json's content as a dict.")
      .def_property_readonly("cost",
                             [](const PlanOutcome& p) { return p.result ? p.result->cost : 0.0; })
      .def_property_readonly("waypoints",
                             [](const PlanOutcome& p) {
                               py::list l;
                               if (!p.result) return l;
                               for (const Pose2& w : p.result->waypoints) l.append(poseTuple(w));
                               return l;
                             })
      .def_property_readonly(
          "tree_edges",
          [](const PlanOutcome& p) {
            py::list l;
            if (!p.result) return l;
            for (const Trajectory& e : p.result->tree_edges) {
              l.append(trajectoryArray(e, p.scenario->robot));
            }
            return l;
          },
          "Every tree edge as a structured array (when record_tree).")
      .def_property_readonly("setup", [](const PlanOutcome& p) { return p.setup; })
      .def("__repr__", [](const PlanOutcome& p) {
        return "<parksim.PlanResult " + p.status() + ": " + p.message() + ">";
      });

  m.def(
      "plan",
      [](const WorldHandle& world, const py::kwargs& kwargs) {
        py::dict options = optionsDict(kwargs);
        EpisodeRequest request;
        request.world = world.world;
        takeComponents(options, request);
        request.plan = planSetupFrom(options);
        request.drive = false;
        const IsolationOptions isolation = takeIsolation(options);
        rejectUnknownOptions(options, "plan");
        return planWorld(world, request, isolation.applyTo(request));
      },
      py::arg("world"),
      R"(Plans the world's parking manoeuvre, as `parksim plan` does.

Options (keywords; the defaults are the library's, the same as `parksim plan`'s and a sweep's):
  planner (a registered name: time-a-star, hybrid-a-star, rrt, rrt-goal-connect, rrt-star,
  rrt-connect, or a plugin's), planner_params (a dict of the planner's own parameters, e.g.
  {"goal_bias": 0.1}; `parksim list` prints them), steering (balkcom-mason, reeds-shepp,
  rotate-translate-rotate, move-to-pose), any SearchDef field (seed, max_iterations: 0 for
  the lot's budget, smooth, smoothing_attempts, ...), and any PlanSetup field (timing, feedback_headroom, goal_tolerance_fraction,
  move_to_pose={...}, reeds_shepp={...}, validation={...}). parksim.PlanSetup() shows every
  default. Releases the GIL while planning.
isolate=True plans in a worker process, as parksim.sweep's workers run: a Python object or a
  plugin that crashes, or plans longer than planner_timeout (s, default 600), gives
  planner_error instead of ending the interpreter. planner_timeout also stops a command
  planner's program (without isolate too).)");

  m.def(
      "read_trajectory",
      [](const WorldHandle& world, const std::string& path) {
        return trajectoryArray(readTrajectoryCsv(path, world.scenario->robot),
                               world.scenario->robot);
      },
      py::arg("world"), py::arg("path"), "A trajectory.csv as a structured array.");
}

}  // namespace parksim::python
