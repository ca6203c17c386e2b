// parksim.sweep(): a sweep spec run from Python with Python planners and controllers beside the
// spec's own (sweep/run/SweepJob.h, the library call `parksim sweep` makes). The Python objects run
// in worker processes forked from the calling thread, so a crash or a hang in one is that
// episode's planner_error or controller_error and the sweep goes on.

#include <Python.h>

#include "parksim/sweep/run/SweepJob.h"
#include "parksim/usercode/PluginLoader.h"
#include "python/src/Bindings.h"
#include "python/src/UserCode.h"

namespace parksim::python {
namespace {

py::dict sweep(const std::string& spec, const std::string& out, const py::dict& planners,
               const py::dict& controllers, const std::vector<std::string>& plugins, int workers,
               const std::string& shard, double planner_timeout_s, double controller_timeout_s) {
  auto extra = std::make_shared<Components>(*loadComponents(plugins));
  for (const auto& [name, obj] : planners) {
    addPythonPlanner(*extra, py::reinterpret_borrow<py::object>(obj), py::str(name));
  }
  for (const auto& [name, obj] : controllers) {
    addPythonController(*extra, py::reinterpret_borrow<py::object>(obj), py::str(name));
  }
  SweepRunnerDef def;
  def.workers = workers > 0 ? workers : defaultSweepWorkers();
  def.limits.planner_s = planner_timeout_s;
  def.limits.controller_tick_s = controller_timeout_s;
  checkSweepRunnerDef(def);
  // The interpreter's own fork handling (its locks, os.register_at_fork callbacks).
  def.fork_hooks.before = [] { PyOS_BeforeFork(); };
  def.fork_hooks.after_in_parent = [] { PyOS_AfterFork_Parent(); };
  def.fork_hooks.after_in_child = [] { PyOS_AfterFork_Child(); };
  // A plugin's constructors are made to check their parameters in a process forked the same way.
  const SweepPlan plan = prepareSweep(
      spec, extra.get(), {.limits = def.limits, .hooks = def.fork_hooks, .isolate = true});
  // Ctrl-C ends the sweep at the next row, as it ends `parksim sweep` (the rows written stay;
  // the running episodes' workers are killed).
  const auto interruptible = [](const SweepProgress&) {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
  const SweepJobResult r = runSweepJob(plan, parseShard(shard), out, def, {}, interruptible);
  py::dict result;
  result["episodes"] = r.episodes.size();
  result["ran"] = r.progress.ran;
  result["met"] = r.episodes.size() - r.failed;
  result["failed"] = r.failed;
  result["elapsed_s"] = r.progress.elapsed_s;
  result["results"] = out + "/results.jsonl";
  return result;
}

}  // namespace

void bindSweep(py::module_& m) {
  m.def("sweep", &sweep, py::arg("spec"), py::kw_only(), py::arg("out"),
        py::arg("planners") = py::dict(), py::arg("controllers") = py::dict(),
        py::arg("plugins") = std::vector<std::string>{}, py::arg("workers") = 0,
        py::arg("shard") = "0/1", py::arg("planner_timeout") = UserCodeLimits{}.planner_s,
        py::arg("controller_timeout") = UserCodeLimits{}.controller_tick_s,
        R"doc(Runs the sweep spec `spec` into `out` as `parksim sweep SPEC --out OUT` does: the
same episodes, ids, results table, seals and resume (episodes already in `out` are not run
again). `planners` and `controllers` map names, which the spec's planners: and controllers:
axes may then list, to Python objects (as run() takes them); `plugins` adds shared libraries to
the spec's own. User code runs in `workers` worker processes (default: one per CPU); a crash or
a hang past `planner_timeout` (s, per plan) or `controller_timeout` (s, per command) is that
episode's planner_error or controller_error. `shard` is "I/N". Returns counts: episodes (of the
shard), ran (now), met, failed, elapsed_s, and the path of results.jsonl.)doc");
}

}  // namespace parksim::python
