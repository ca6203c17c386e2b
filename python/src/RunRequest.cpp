// How plan() and run() run their request: in this process with the GIL released, or with
// isolate=True in a watched worker (pipeline/IsolatedEpisode.h, the mechanism parksim.sweep's
// workers use), so that a Python object or a plugin that crashes or hangs past its time limit is
// a verdict instead of the end of the interpreter.

#include <Python.h>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/pipeline/IsolatedEpisode.h"
#include "python/src/Conversions.h"

namespace parksim::python {

IsolationOptions takeIsolation(py::dict& options) {
  const auto take = [&options](const char* key) -> py::object {
    if (!options.contains(key)) return py::none();
    return options.attr("pop")(key);
  };
  IsolationOptions o;
  if (const py::object v = take("isolate"); !v.is_none()) o.isolate = v.cast<bool>();
  if (const py::object v = take("planner_timeout"); !v.is_none()) o.planner_s = v.cast<double>();
  if (const py::object v = take("controller_timeout"); !v.is_none()) {
    o.controller_tick_s = v.cast<double>();
  }
  return o;
}

bool IsolationOptions::applyTo(EpisodeRequest& request) const {
  if (planner_s) request.limits.planner_s = *planner_s;
  if (controller_tick_s) request.limits.controller_tick_s = *controller_tick_s;
  checkUserCodeLimits(request.limits);
  // A limit on code in this process would do nothing: refused rather than ignored. A command's
  // program is stopped at it wherever the episode runs.
  if ((planner_s || controller_tick_s) && !isolate && runsUserCode(request)) {
    throw py::type_error(
        "planner_timeout and controller_timeout stop a Python object's or a plugin's code only "
        "in a worker process: pass isolate=True");
  }
  return isolate;
}

EpisodeOutcome runRequest(const EpisodeRequest& request, bool isolate) {
  if (!isolate) {
    py::gil_scoped_release release;
    return runEpisodePipeline(request);
  }
  // The GIL is released while the worker runs and taken for the fork, around which the
  // interpreter does its own fork handling (its locks, os.register_at_fork callbacks); the
  // worker keeps it, and its Python objects run there as they would here.
  PyGILState_STATE gil{};
  ForkHooks hooks;
  hooks.before = [&gil] {
    gil = PyGILState_Ensure();
    PyOS_BeforeFork();
  };
  hooks.after_in_parent = [&gil] {
    PyOS_AfterFork_Parent();
    PyGILState_Release(gil);
  };
  hooks.after_in_child = [] { PyOS_AfterFork_Child(); };
  py::gil_scoped_release release;
  return runEpisodeIsolated(request, hooks);
}

}  // namespace parksim::python
