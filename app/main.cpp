// parksim: plan, simulate, render and benchmark parking manoeuvres of a two-wheel robot.

#include <cstdio>
#include <exception>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/Command.h"
#include "parksim/core/Error.h"
#include "parksim/core/Provenance.h"

int main(int argc, char** argv) {
  using namespace parksim::app;
  CLI::App app{"parksim: plan, simulate, render and benchmark parking manoeuvres"};
  app.require_subcommand(1);
  const std::string version = parksim::versionLine(parksim::buildProvenance());
  app.set_version_flag("--version", version, "print parksim's version and build, then exit");
  std::vector<std::pair<CLI::App*, CommandRunner>> commands;
  auto add = [&](const char* name, const char* help, CommandRunner (*setup)(CLI::App&)) {
    CLI::App* sub = app.add_subcommand(name, help);
    sub->set_version_flag("--version", version);
    commands.emplace_back(sub, setup(*sub));
  };
  add("plan", "plan a parking manoeuvre and write trajectory.csv and plan.json", setupPlanCommand);
  add("run", "plan (or load a plan), drive it in the Bullet simulation and measure tracking",
      setupRunCommand);
  add("render", "draw the study's figures for a world, without running an episode",
      setupRenderCommand);
  add("bench", "benchmark parksim's planners, optionally against OMPL", setupBenchCommand);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints help (success) or the usage error; usage errors exit 2 like any bad input.
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, run] : commands) {
      if (sub->parsed()) return run();
    }
  } catch (const parksim::Error& e) {
    std::fprintf(stderr, "parksim: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "parksim: internal error: %s\n", e.what());
    return 3;
  }
  return 2;
}
