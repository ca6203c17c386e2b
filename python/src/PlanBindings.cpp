// parksim.plan() and its result: the episode pipeline without driving, as `parksim plan`.
// Options map onto PlanSetup and SearchDef (DefBindings.cpp); the statistics are plan.json's
// (results/PlanFile.h), so the two never drift apart.

#include <pybind11/stl.h>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/results/TrajectoryFile.h"
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

PlanOutcome planWorld(const WorldHandle& world, const EpisodeRequest& request) {
  EpisodeRequest plan_only = request;
  plan_only.drive = false;
  py::gil_scoped_release release;
  EpisodeOutcome out = runEpisodePipeline(plan_only);
  return {world.scenario, out.plan_setup, std::move(*out.plan), std::move(out.plan_summary)};
}

void bindPlan(py::module_& m) {
  py::class_<PlanOutcome>(m, "PlanResult", "A plan: status, trajectory and statistics.")
      .def_property_readonly("solved", [](const PlanOutcome& p) { return p.result.solved(); })
      .def_property_readonly("status",
                             [](const PlanOutcome& p) { return toString(p.result.status); })
      .def_property_readonly("message", [](const PlanOutcome& p) { return p.result.message; })
      .def_property_readonly(
          "trajectory",
          [](const PlanOutcome& p) {
            return trajectoryArray(p.result.trajectory, p.scenario->robot);
          },
          "Structured array with trajectory.csv's columns t, x, y, theta, omega_left, "
          "omega_right, v, omega (s, m, rad, rad/s, m/s); empty unless solved.")
      .def_property_readonly(
          "stats", [](const PlanOutcome& p) { return toPython(p.summary); },
          "plan.json's content as a dict.")
      .def_property_readonly("cost", [](const PlanOutcome& p) { return p.result.cost; })
      .def_property_readonly("waypoints",
                             [](const PlanOutcome& p) {
                               py::list l;
                               for (const Pose2& w : p.result.waypoints) l.append(poseTuple(w));
                               return l;
                             })
      .def_property_readonly(
          "tree_edges",
          [](const PlanOutcome& p) {
            py::list l;
            for (const Trajectory& e : p.result.tree_edges) {
              l.append(trajectoryArray(e, p.scenario->robot));
            }
            return l;
          },
          "Every tree edge as a structured array (when record_tree).")
      .def_property_readonly("setup", [](const PlanOutcome& p) { return p.setup; })
      .def("__repr__", [](const PlanOutcome& p) {
        return "<parksim.PlanResult " + std::string(toString(p.result.status)) + ": " +
               p.result.message + ">";
      });

  m.def(
      "plan",
      [](const WorldHandle& world, const py::kwargs& kwargs) {
        py::dict options = optionsDict(kwargs);
        EpisodeRequest request;
        request.world = world.world;
        takeComponents(options, request);
        request.plan = planSetupFrom(options);
        rejectUnknownOptions(options, "plan");
        return planWorld(world, request);
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
  default. Releases the GIL while planning.)");

  m.def(
      "read_trajectory",
      [](const WorldHandle& world, const std::string& path) {
        return trajectoryArray(readTrajectoryCsv(path, world.scenario->robot),
                               world.scenario->robot);
      },
      py::arg("world"), py::arg("path"), "A trajectory.csv as a structured array.");
}

}  // namespace parksim::python
