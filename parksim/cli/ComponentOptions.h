#pragma once
// The options that choose code by name: --plugin PATH (repeatable) loads plugins whose
// planners and controllers --planner and --controller may then name; --controller and
// --controller-param (or --controller-command) choose the controller that drives closed-loop
// tracking.

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "parksim/core/params/ParamMap.h"
#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/usercode/Components.h"

namespace parksim::cli {

struct PluginOptions {
  std::vector<std::string> paths;

  void addTo(CLI::App& sub);
  /// parksim's own planners and controllers plus those of every plugin, loaded in order. Throws
  /// Error naming the file when one cannot be loaded.
  std::shared_ptr<const Components> load() const;
};

struct ControllerOptions {
  std::string name = kDefaultController;
  std::vector<std::string> params;  ///< NAME=VALUE
  /// --controller-command 'CMD ...': sets `name` to the controller `command` with this command
  /// line as its `command` parameter (usercode/CommandController.h); excludes --controller.
  std::string command;

  void addTo(CLI::App& sub);
  /// The parameters as a ParamMap (canonical text); throws Error on an entry without '='.
  ParamMap paramMap() const;
};

/// --planner-timeout and --controller-timeout: the limits on user code (UserCodeWatch.h): a
/// plugin's runs in a watched child process, a command stops its own program at them
/// (EpisodeRequest::limits).
struct UserCodeOptions {
  UserCodeLimits limits;

  void addTo(CLI::App& sub);
};

/// "NAME=VALUE" entries of `option` as a ParamMap; a name given twice is an error.
ParamMap paramMapFrom(const std::vector<std::string>& entries, const std::string& option);

}  // namespace parksim::cli
