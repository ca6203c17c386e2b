#pragma once
// Shared by the binding files of the Python module parksim._parksim: one bind function per
// concept (Module.cpp calls them in order), and the conversions they all use.

#include <memory>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/scenario/world/World.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim::python {

namespace py = pybind11;

void bindDefs(py::module_& m);      // DefBindings.cpp: the ...Def structs, options as kwargs
void bindRobot(py::module_& m);     // RobotBindings.cpp: RobotDef, checked as a world file
void bindWorld(py::module_& m);     // WorldBindings.cpp: World, load_world, collision, C-space
void bindPlan(py::module_& m);      // PlanBindings.cpp: plan(), PlanResult, trajectories
void bindEpisode(py::module_& m);   // EpisodeBindings.cpp: run(), Episode, DynamicsWorld
void bindRender(py::module_& m);    // RenderBindings.cpp: images, figures, FrameRecorder
void bindTasks(py::module_& m);     // TaskBindings.cpp: the reinforcement-learning tasks
void bindUserCode(py::module_& m);  // UserCodeBindings.cpp: Python planners and controllers
void bindSweep(py::module_& m);     // SweepBindings.cpp: sweep()

/// A loaded world (scenario/world/World.h): immutable, shared by every plan and episode made from
/// it. It keeps the text it was read from, so that it pickles as that text and re-reads it.
struct WorldHandle {
  WorldHandle(std::shared_ptr<const World> w, std::string text, std::string name)
      : world(std::move(w)),
        scenario(world, &world->scenario),
        source_text(std::move(text)),
        source_name(std::move(name)) {}
  std::shared_ptr<const World> world;
  std::shared_ptr<const Scenario> scenario;  ///< world->scenario, sharing its lifetime
  std::string source_text;                   ///< the world file's text (or the dict's YAML)
  std::string source_name;                   ///< its path (or the name given to a dict)
};

/// The episode request (pipeline/EpisodeRequest.h) plan(), run() and Episode() make: the
/// library's defaults, with the options in `options` taken from it (and removed): planner
/// options when `planning` (planner, planner_params, steering, SearchDef and PlanSetup fields),
/// then realism (a preset name or "world"), noise_seed, realisations, min_success_fraction,
/// tolerance (a dict of ToleranceOverrides' bounds) and any ExecutionDef field (tracking, gains,
/// ...).
EpisodeRequest requestFrom(const WorldHandle& world, py::dict& options, bool planning);

/// Copies the keys of `options` that name a field of `def`'s Python class onto it, removing
/// them from `options`. Fields are the class's properties (DefBindings.cpp), so a field added to
/// a Def's binding is an option everywhere that Def is taken.
template <class Def>
Def takeOptions(const Def& def, py::dict& options) {
  py::object obj = py::cast(def);
  py::object type = py::type::of(obj);
  const py::object property = py::module_::import("builtins").attr("property");
  for (const py::handle key : py::list(options.attr("keys")())) {
    const std::string name = py::str(key);
    if (name.empty() || name[0] == '_' || !py::hasattr(type, name.c_str())) continue;
    if (!py::isinstance(type.attr(name.c_str()), property)) continue;
    obj.attr(name.c_str()) = options[key];
    PyDict_DelItem(options.ptr(), key.ptr());
  }
  return obj.cast<Def>();
}

/// Throws TypeError naming the keys left in `options`.
void rejectUnknownOptions(const py::dict& options, const std::string& function);

/// A Def from a Def object or a dict of its fields (errors in them raised as they are).
template <class Def>
Def defFrom(const py::handle& value, const std::string& what) {
  if (py::isinstance<Def>(value)) return value.cast<Def>();
  if (!py::isinstance<py::dict>(value)) {
    const std::string name = py::str(py::type::of<Def>().attr("__name__"));
    throw py::type_error(what + " must be a dict or a " + name);
  }
  py::dict options(value.cast<py::dict>());
  Def def = takeOptions(Def{}, options);
  rejectUnknownOptions(options, what);
  return def;
}

/// A copy of `kwargs` as a dict we may consume.
py::dict optionsDict(const py::kwargs& kwargs);

/// (x, y, theta) from any sequence of three numbers.
Pose2 poseFrom(const py::handle& sequence);
py::tuple poseTuple(const Pose2& pose);
/// N x 3 array: x, y, theta per pose.
py::array posesArray(const std::vector<Pose2>& poses);

/// JSON values as Python objects (dict, list, str, float, int, bool, None).
py::object toPython(const nlohmann::json& json);

/// The plan as a structured array: t, x, y, theta, omega_left, omega_right, v, omega.
py::array trajectoryArray(const Trajectory& trajectory, const RobotDef& robot);
/// A trajectory from a PlanResult, a structured array with fields t, x, y, theta, omega_left,
/// omega_right (others ignored), or a trajectory.csv path (read for `robot`: a car's file holds
/// v and steer_rad, results/TrajectoryFile.h).
Trajectory trajectoryFrom(const py::handle& plan, const RobotDef& robot = {});
/// Executed rows as a structured array with executed.csv's columns (its realism columns too
/// when `realism_columns`, as executedCsv writes them under an active realism).
py::array executedArray(const std::vector<ExecutedRow>& rows, bool realism_columns);

}  // namespace parksim::python
