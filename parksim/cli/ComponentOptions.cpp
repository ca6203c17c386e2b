#include "parksim/cli/ComponentOptions.h"

#include "parksim/cli/Validators.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/params/ParamSet.h"
#include "parksim/usercode/CommandController.h"
#include "parksim/usercode/CommandLine.h"
#include "parksim/usercode/PluginLoader.h"

namespace parksim::cli {

void PluginOptions::addTo(CLI::App& sub) {
  sub.add_option("--plugin", paths,
                 "a plugin (shared library, docs/your-code.md) whose planners and controllers "
                 "--planner and --controller may name; repeatable");
}

std::shared_ptr<const Components> PluginOptions::load() const { return loadComponents(paths); }

void ControllerOptions::addTo(CLI::App& sub) {
  CLI::Option* by_name =
      sub.add_option("--controller", name,
                     "controller for closed-loop tracking, by name: " +
                         joinNames(ownControllers().names()) +
                         " (or a plugin's); `parksim list` shows them with their parameters")
          ->capture_default_str();
  sub.add_option("--controller-param", params,
                 "NAME=VALUE: a parameter of the selected controller (repeatable)");
  sub.add_option("--controller-command", command,
                 "'CMD ...': control with a process in any language, run without a shell, one "
                 "line per control tick on its stdin, 'LEFT RIGHT' back (the controller "
                 "`command`, docs/your-code.md)")
      ->excludes(by_name)
      ->each([this](const std::string&) { name = kCommandController; });
}

void UserCodeOptions::addTo(CLI::App& sub) {
  sub.add_option("--planner-timeout", limits.planner_s,
                 "a user's planner (plugin, command) is stopped after this long, s (a command at "
                 "its own timeout_s when that is shorter)")
      ->capture_default_str()
      ->check(realIn(UserCodeLimits::kMin, UserCodeLimits::kMax));
  sub.add_option("--controller-timeout", limits.controller_tick_s,
                 "a user's controller (plugin, command) is stopped when one command (its reset "
                 "included) takes longer, s (a command at its own timeouts when they are shorter)")
      ->capture_default_str()
      ->check(realIn(UserCodeLimits::kMin, UserCodeLimits::kMax));
}

ParamMap ControllerOptions::paramMap() const {
  ParamMap out = paramMapFrom(params, "--controller-param");
  if (!command.empty()) {
    if (out.count(kCommandParam) != 0) {
      throw Error("--controller-command and --controller-param command=... both give the command");
    }
    out[kCommandParam] = quoteCommandLine(splitCommandLine(command, "--controller-command"));
  }
  return out;
}

ParamMap paramMapFrom(const std::vector<std::string>& entries, const std::string& option) {
  ParamMap out;
  for (const std::string& text : entries) {
    auto [name, value] = splitParamAssignment(text, option);
    if (!out.emplace(name, canonicalParamText(value)).second) {
      throw Error(option + ": " + name + " given twice");
    }
  }
  return out;
}

}  // namespace parksim::cli
