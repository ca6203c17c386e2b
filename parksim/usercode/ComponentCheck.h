#pragma once
// Checking a planner's or a controller's parameters means making one with them and dropping
// it: its factory applies them (an unknown name or a bad value throws) and its constructor may
// refuse them. A plugin's constructor is user code. Front-ends that run a plugin's components in
// a watched process (UserCodeIsolation.h: `parksim run`, `plan`, `render` and sweeps) check them
// in one too (ComponentCheckDef::isolate), so a crash or a hang there is a one-line error naming
// it, not the end of parksim. Everything else is made in the calling process: parksim's own
// components, commands (separate programs already), Python objects (their constructors run the
// interpreter, which is not forked without its hooks), every component when the caller already
// runs under a watch (an episode's worker process, which then names the component a constructor
// crashes or hangs in), and a plugin's when the caller runs it in its own process anyway (the
// library's runEpisodePipeline, Python's run()).

#include <cstddef>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "parksim/core/params/ParamMap.h"
#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/usercode/Components.h"
#include "parksim/usercode/UserCodeIsolation.h"

namespace parksim {

/// A planner or a controller, with the parameters it is to be made with.
struct ComponentParams {
  enum class Kind { kPlanner, kController };
  Kind kind = Kind::kPlanner;
  std::string name;
  ParamMap params;

  bool operator<(const ComponentParams& o) const {
    return std::tie(kind, name, params) < std::tie(o.kind, o.name, o.params);
  }
  bool operator==(const ComponentParams& o) const {
    return std::tie(kind, name, params) == std::tie(o.kind, o.name, o.params);
  }
};

/// Where a plugin's components are made.
struct ComponentCheckDef {
  /// The time a constructor may take: limits.planner_s for a planner's, limits.controller_tick_s
  /// for a controller's (the user code limits of the run the check is for).
  UserCodeLimits limits;
  /// Called around the fork (an embedding interpreter's).
  ForkHooks hooks;
  /// Set when the caller already runs under a watch: every component is made here, the watch
  /// told when a user's constructor runs. Not owned.
  UserCodeWatch* watch = nullptr;
  /// Make a plugin's components in a watched process (without a watch): for callers that run
  /// them in one. Otherwise they are made here, as the run that follows makes them.
  bool isolate = false;
};

/// The first component that cannot be made: its index in the list and the one-line error.
struct ComponentRefusal {
  std::size_t index = 0;
  std::string message;
};

/// Makes each of `list`, in order, and drops it, until one fails: an unknown name, an unknown
/// parameter or a bad value (the registry's message), or a plugin's constructor that crashed or
/// hung ("planner NAME crashed (SIGSEGV, Segmentation fault) while being made to check its
/// parameters"). With def.isolate, a plugin's components are made in one watched process for
/// the whole list, forked at the first of them, from the calling thread (UserCodeIsolation.h: no
/// other thread may hold a lock then); the rest in the calling process. Nothing when all can be
/// made.
std::optional<ComponentRefusal> firstRefusedComponent(const Components& components,
                                                      const std::vector<ComponentParams>& list,
                                                      const ComponentCheckDef& def = {});

/// Throws Error with the message of firstRefusedComponent, if any.
void checkComponents(const Components& components, const std::vector<ComponentParams>& list,
                     const ComponentCheckDef& def = {});

}  // namespace parksim
