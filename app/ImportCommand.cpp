// parksim import MAP --out WORLD.yaml: a map a user already has (a ROS map server YAML and its
// image, an SVG drawing, a Moving AI grid) as a world file to read and edit: the map as a `map:`
// reference (or, with --obstacles, its obstacles written out), the lot from the map's extent,
// the default robot and a start and a goal at two free places of the map. The world is read
// back before it is written; a bad map or an existing --out writes nothing.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/Command.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/MapImport.h"

namespace parksim::app {

CommandRunner setupImportCommand(CLI::App& sub) {
  struct Options {
    MapImportDef def;
    double cell = 0.0;
    double scale = 0.0;
    bool force = false;
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("map", opt->def.map,
                 "the map: a ROS map server YAML (.yaml, beside its PGM or PNG image), an SVG "
                 "drawing (.svg) or a Moving AI grid (.map)")
      ->required();
  sub.add_option("--out", opt->def.world, "the world file to write (YAML)")->required();
  sub.add_option("--cell", opt->cell, "a Moving AI grid's cell size, m")
      ->check(CLI::Range(1e-4, 100.0));
  sub.add_option("--scale", opt->scale,
                 "an SVG drawing's metres per user unit (when its size has no unit)")
      ->check(CLI::Range(1e-9, 1000.0));
  sub.add_option("--layers", opt->def.layers,
                 "an SVG drawing's layers (Inkscape labels, or group ids) that are obstacles")
      ->delimiter(',');
  sub.add_option("--ids", opt->def.ids, "an SVG drawing's element ids that are obstacles")
      ->delimiter(',');
  sub.add_flag("--obstacles", opt->def.list_obstacles,
               "write the map's obstacles into the world instead of referring to the map");
  sub.add_flag("--force", opt->force, "replace --out if it exists");

  return [opt](const OutputOptions&) -> int {
    MapImportDef def = opt->def;
    if (opt->cell > 0.0) def.cell_m = opt->cell;
    if (opt->scale > 0.0) def.scale = opt->scale;
    std::error_code ec;
    if (!opt->force && std::filesystem::exists(def.world, ec)) {
      throw Error("--out " + def.world + ": exists; choose another file or add --force");
    }
    const MapImport imported = importMap(def);
    for (const std::string& w : imported.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    writeFileAtomically(def.world, imported.text);
    const Scenario& s = imported.world.scenario;
    std::printf("imported %s (%s map, %zu obstacle%s) into %s: lot [%g, %g] x [%g, %g] m\n",
                cli::printable(def.map).c_str(), imported.kind.c_str(), s.obstacles.size(),
                s.obstacles.size() == 1 ? "" : "s", cli::printable(def.world).c_str(),
                s.lot.x_min_m, s.lot.x_max_m, s.lot.y_min_m, s.lot.y_max_m);
    std::printf(
        "start (%g, %g) and goal (%g, %g) are two free places the import found: edit them, and "
        "the robot, in %s\n",
        s.start.x, s.start.y, s.goal.pose.x, s.goal.pose.y, cli::printable(def.world).c_str());
    return kExitOk;
  };
}

}  // namespace parksim::app
