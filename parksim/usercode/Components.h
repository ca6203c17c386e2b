#pragma once
// The planners and controllers a run may select by name: parksim's own, plus those of the
// plugins loaded (PluginLoader.h), with a record of each plugin for results. A front-end builds
// one, then hands it to every episode it runs (EpisodeRequest::components).

#include <memory>
#include <string>
#include <vector>

#include "parksim/planner/base/PlannerRegistry.h"
#include "parksim/sim/control/Controller.h"

namespace parksim {

/// A loaded plugin, as results record it: resumes, shards and Slurm tasks load the same code
/// or refuse (sweep.json, metrics.json).
struct PluginRecord {
  std::string name;                      ///< the plugin's own name
  std::string version;                   ///< its own version text
  std::string path;                      ///< the file it was loaded from (absolute)
  std::string hash;                      ///< FNV-1a 64 of the file's bytes, 16 hex digits
  std::vector<std::string> planners;     ///< what it registered
  std::vector<std::string> controllers;  ///< what it registered
};

/// What a run may select without a plugin: parksim's own planners (builtInPlanners) and
/// controllers (builtInControllers), then the command planner and controller, which run a
/// user's program (usercode/CommandPlanner.h, CommandController.h).
PlannerRegistry ownPlanners();
ControllerRegistry ownControllers();

struct Components {
  PlannerRegistry planners = ownPlanners();
  ControllerRegistry controllers = ownControllers();
  std::vector<PluginRecord> plugins;  ///< in load order
};

/// The plugins as results record them: "name version hash" of each, in load order, joined by
/// "; " (empty: none). The `plugins` column of a sweep's rows and metrics.json's
/// provenance.plugins; a resumed or merged table must carry the same.
std::string pluginsProvenance(const Components& components);

/// Where the code of the planner `info` comes from, one line, as plan.json's planner_origin
/// records it: "plugin NAME VERSION (PATH, FNV-1a HASH)", "command `CMD ...`" (its `command`
/// parameter in `params`), or info.origin ("Python object my_module.Straight"); empty for
/// parksim's own.
std::string plannerOrigin(const Components& components, const PlannerInfo& info,
                          const ParamMap& params);

/// parksim's own planners and controllers, no plugins. Built once, shared.
std::shared_ptr<const Components> builtInComponents();

}  // namespace parksim
