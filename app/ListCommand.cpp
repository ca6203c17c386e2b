// parksim list [--plugin PATH]...: the planners and controllers --planner and --controller may
// name, with their parameters (name, default, range, meaning), and the plugins loaded.

#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/Command.h"
#include "parksim/cli/ComponentOptions.h"
#include "parksim/cli/TerminalText.h"

namespace parksim::app {

namespace {

nlohmann::ordered_json paramsJson(const std::vector<ParamInfo>& params) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ParamInfo& p : params) {
    out.push_back({{"name", p.name},
                   {"default", p.default_text},
                   {"range", p.range},
                   {"description", p.description}});
  }
  return out;
}

template <class Info>
nlohmann::ordered_json infoJson(const Info& info) {
  return {{"name", info.name},
          {"description", info.description},
          {"plugin", info.plugin},
          {"params", paramsJson(info.params)}};
}

template <class Info>
void printInfo(const Info& info) {
  std::printf("  %-18s %s%s\n", cli::printable(info.name).c_str(),
              cli::printable(info.description).c_str(),
              info.plugin.empty() ? "" : (" (plugin " + cli::printable(info.plugin) + ")").c_str());
  for (const ParamInfo& p : info.params) {
    std::printf("      %s = %s  %s: %s\n", cli::printable(p.name).c_str(),
                cli::printable(p.default_text).c_str(), cli::printable(p.range).c_str(),
                cli::printable(p.description).c_str());
  }
}

}  // namespace

CommandRunner setupListCommand(CLI::App& sub) {
  struct Options {
    cli::PluginOptions plugins;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  opt->plugins.addTo(sub);
  sub.add_flag("--json", opt->json, "print it as JSON");
  return [opt](const OutputOptions&) -> int {
    const std::shared_ptr<const Components> c = opt->plugins.load();
    if (opt->json) {
      nlohmann::ordered_json j;
      j["planners"] = nlohmann::ordered_json::array();
      for (const PlannerEntry& e : c->planners.entries()) {
        nlohmann::ordered_json p = infoJson(e.info);
        p["uses_steering"] = e.info.uses_steering;
        p["anytime"] = e.info.anytime;
        j["planners"].push_back(p);
      }
      j["controllers"] = nlohmann::ordered_json::array();
      for (const ControllerEntry& e : c->controllers.entries()) {
        j["controllers"].push_back(infoJson(e.info));
      }
      j["plugins"] = nlohmann::ordered_json::array();
      for (const PluginRecord& r : c->plugins) {
        j["plugins"].push_back({{"name", r.name},
                                {"version", r.version},
                                {"path", r.path},
                                {"hash", r.hash},
                                {"planners", r.planners},
                                {"controllers", r.controllers}});
      }
      std::printf("%s\n", j.dump(2).c_str());
      return kExitOk;
    }
    std::printf("planners (--planner NAME, --planner-param NAME=VALUE):\n");
    for (const PlannerEntry& e : c->planners.entries()) printInfo(e.info);
    std::printf("controllers (--controller NAME, --controller-param NAME=VALUE):\n");
    for (const ControllerEntry& e : c->controllers.entries()) printInfo(e.info);
    for (const PluginRecord& r : c->plugins) {
      std::printf("plugin %s %s: %s (FNV-1a %s)\n", cli::printable(r.name).c_str(),
                  cli::printable(r.version).c_str(), cli::printable(r.path).c_str(),
                  r.hash.c_str());
    }
    return kExitOk;
  };
}

}  // namespace parksim::app
