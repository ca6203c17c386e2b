// A world's `map:` section: maps beside the world, next to hand-written obstacles, the lot from
// the maps' extent, names, the content hash, overrides of map fields and located refusals.

#include "parksim/scenario/world/World.h"

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/MapFiles.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

// A 2 x 1 m ROS map at 0.1 m: a wall along its bottom row, origin (1, 1).
fs::path writeLab(const std::string& name) {
  const fs::path dir = testing::freshDir(name);
  std::vector<std::vector<int>> rows(10, std::vector<int>(20, 254));
  rows[9] = std::vector<int>(20, 0);
  rows[0][0] = 205;  // unknown, top-left
  testing::writePgm(dir / "lab.pgm", rows);
  testing::writeText(dir / "lab.yaml", "image: lab.pgm\nresolution: 0.1\norigin: [1, 1, 0]\n");
  testing::writeText(dir / "g.map", "type octile\nheight 2\nwidth 2\nmap\n@.\n..\n");
  return dir;
}

const std::string kRest = "start: [1.5, 1.5, 0]\ngoal: {pose: [2.5, 1.5, 0]}\n";

std::string errorOf(const fs::path& world, const std::vector<ScenarioOverride>& o = {}) {
  try {
    (void)loadWorld(world.string(), o);
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(MapSection, MapsBesideHandWrittenObstaclesWithTheLotFromTheirExtent) {
  const fs::path dir = writeLab("map_section_lot");
  testing::writeText(
      dir / "w.yaml",
      "format: parksim-world/1\nname: w\nmap:\n"
      "  - {ros: lab.yaml, height: 0.3}\n"
      "  - {movingai: g.map, cell: 0.5, origin: [3, 1], name: grid}\n"
      "obstacles:\n  - {name: post, kind: bollard, center: [2, 1.8], radius: 0.05}\n" +
          kRest);
  const World w = loadWorld((dir / "w.yaml").string());
  const Scenario& s = w.scenario;
  ASSERT_EQ(s.obstacles.size(), 3u);
  EXPECT_EQ(s.obstacles[0].name, "lab");  // the file's stem
  EXPECT_EQ(s.obstacles[0].kind, ObstacleKind::kWall);
  EXPECT_EQ(s.obstacles[0].height_m, 0.3);
  EXPECT_EQ(s.obstacles[0].compound->parts.size(), 2u);  // the wall and the unknown cell
  EXPECT_EQ(s.obstacles[1].name, "grid");
  EXPECT_EQ(s.obstacles[2].name, "post");
  // The lot: the maps' extent, x from 1 (lab) to 4 (grid), y from 1 to 2.
  EXPECT_DOUBLE_EQ(s.lot.x_min_m, 1.0);
  EXPECT_DOUBLE_EQ(s.lot.x_max_m, 4.0);
  EXPECT_DOUBLE_EQ(s.lot.y_min_m, 1.0);
  EXPECT_DOUBLE_EQ(s.lot.y_max_m, 2.0);
  ASSERT_EQ(s.maps.size(), 2u);
  EXPECT_EQ(s.maps[0].grid->width, 20);
  EXPECT_EQ(s.maps[0].source, (dir / "lab.yaml").lexically_normal().string());

  // The map's image is part of the world: editing it changes the content hash.
  const std::string before = w.content_hash;
  std::vector<std::vector<int>> rows(10, std::vector<int>(20, 254));
  rows[9] = std::vector<int>(20, 0);
  testing::writePgm(dir / "lab.pgm", rows);
  EXPECT_NE(loadWorld((dir / "w.yaml").string()).content_hash, before);
  // A lot given in the file wins.
  testing::writeText(dir / "w2.yaml",
                     "format: parksim-world/1\nname: w\nmap:\n  - {ros: lab.yaml}\n"
                     "lot: {x_min: 0, y_min: 0, x_max: 5, y_max: 5}\n" +
                         kRest);
  EXPECT_EQ(loadWorld((dir / "w2.yaml").string()).scenario.lot.x_max_m, 5.0);
}

// The ROS reader's warnings reach the world, for the front ends to print.
TEST(MapSection, AWorldCarriesItsMapsWarnings) {
  const fs::path dir = writeLab("map_section_warnings");
  testing::writeText(dir / "lab.yaml",
                     "image: lab.pgm\nresolution: 0.1\norigin: [1, 1, 0]\ncenterline: []\n");
  testing::writeText(dir / "w.yaml",
                     "format: parksim-world/1\nname: w\nmap:\n  - {ros: lab.yaml}\n" + kRest);
  const World w = loadWorld((dir / "w.yaml").string());
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(
      w.warnings[0].rfind((dir / "lab.yaml").lexically_normal().string() + ":4: centerline: ", 0),
      0u)
      << w.warnings[0];
}

TEST(MapSection, OverridesReachMapFieldsAndUnknownCellsFollowTheWorld) {
  const fs::path dir = writeLab("map_section_set");
  testing::writeText(dir / "w.yaml",
                     "format: parksim-world/1\nname: w\nmap:\n  - {ros: lab.yaml}\n" + kRest);
  const auto parts = [&](const std::vector<ScenarioOverride>& o) {
    return loadWorld((dir / "w.yaml").string(), o).scenario.obstacles[0].compound->parts.size();
  };
  EXPECT_EQ(parts({}), 2u);
  EXPECT_EQ(parts({{"map[0].unknown", "free", "--set map[0].unknown=free"}}), 1u);
  const Scenario inflated = loadWorld((dir / "w.yaml").string(),
                                      {{"map[0].inflation", "0.1", "--set map[0].inflation=0.1"}})
                                .scenario;
  // The wall row grows by a row of cells: its top rises from y 1.1 to 1.2.
  EXPECT_NEAR(inflated.obstacles[0].compound->extent.max().y(), 2.0,
              1e-12);  // the unknown cell grew
  EXPECT_EQ(errorOf(dir / "w.yaml", {{"map[0].inflation", "-1", "--set map[0].inflation=-1"}}),
            "--set map[0].inflation=-1: map[0].inflation: must be in [0, 100] m, got -1");
}

TEST(MapSection, BadEntriesAndBadMapsAreRefusedAtTheWorldsLine) {
  const fs::path dir = writeLab("map_section_bad");
  const std::string w = (dir / "w.yaml").string();
  const std::string d = dir.string() + "/";
  const auto world = [&](const std::string& map) {
    testing::writeText(dir / "w.yaml", "format: parksim-world/1\nname: w\nmap:\n" + map + kRest);
    return errorOf(dir / "w.yaml");
  };
  EXPECT_EQ(world("  - {ros: none.yaml}\n"),
            w + ":4: map[0].ros: " + d +
                "none.yaml: cannot open ROS map YAML: No such file or "
                "directory");
  EXPECT_EQ(world("  - {ros: lab.yaml, svg: x.svg}\n"),
            w + ":4: map[0]: a map entry names its kind once: ros: <map.yaml>, svg: "
                "<drawing.svg> or movingai: <grid.map>");
  EXPECT_EQ(world("  - {movingai: g.map}\n"), w + ":4: map[0].cell: missing required field");
  EXPECT_EQ(world("  - {ros: lab.yaml, unknown: maybe}\n"),
            w + ":4: map[0].unknown: must be occupied or free, got \"maybe\"");
  EXPECT_EQ(world("  - {ros: lab.yaml, name: post}\n  - {ros: lab.yaml, name: post}\n"),
            w + ":3: map: duplicate name \"post\" (already used at line 3)");
  testing::writeText(dir / "nan.yaml", "image: lab.pgm\nresolution: .nan\norigin: [0, 0, 0]\n");
  EXPECT_EQ(
      world("  - {ros: nan.yaml}\n"),
      w + ":4: map[0].ros: " + d + "nan.yaml:2: resolution: must be a finite number, got .nan");
  // Without lot: and without maps there is no lot.
  testing::writeText(dir / "w.yaml", "format: parksim-world/1\nname: w\n" + kRest);
  EXPECT_EQ(errorOf(dir / "w.yaml"), w + ":1: lot: missing required field");
  // The start must stand clear of the map's wall like any obstacle's.
  testing::writeText(dir / "w.yaml",
                     "format: parksim-world/1\nname: w\nmap: [{ros: lab.yaml}]\n"
                     "start: [1.5, 1.05, 0]\ngoal: {pose: [2.5, 1.5, 0]}\n");
  EXPECT_EQ(errorOf(dir / "w.yaml"), w + ":4: start: robot footprint overlaps obstacle \"lab\"");
  // Nothing was read when the map is bad: the world's own first error stands.
}

}  // namespace
}  // namespace parksim
