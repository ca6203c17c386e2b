// A map as a world file to edit: the map: reference or its obstacles written out, a lot from
// its extent, free placeholders for start and goal; a world that loads, or nothing.

#include "parksim/scenario/world/MapImport.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/support/MapFiles.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

// Whether any obstacle blocks the footprint at `pose`.
bool blocked(const Scenario& s, const Pose2& pose) {
  const OrientedBox fp = footprintAt(s.robot, pose);
  for (const Obstacle& o : s.obstacles) {
    if (separation(fp, o) < 0.0) return true;
  }
  return false;
}

void expectSameObstacles(const Scenario& a, const Scenario& b) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> x(a.lot.x_min_m, a.lot.x_max_m);
  std::uniform_real_distribution<double> y(a.lot.y_min_m, a.lot.y_max_m);
  std::uniform_real_distribution<double> yaw(-3.14, 3.14);
  int hits = 0;
  for (int k = 0; k < 4000; ++k) {
    const Pose2 p{x(rng), y(rng), yaw(rng)};
    ASSERT_EQ(blocked(a, p), blocked(b, p)) << p.x << ", " << p.y;
    hits += blocked(a, p);
  }
  EXPECT_GT(hits, 100);
}

TEST(MapImport, WritesAWorldThatLoadsWithTheMapOrItsObstacles) {
  const fs::path src = fs::path(testing::sourceDir()) / "worlds" / "maps";
  const fs::path dir = testing::freshDir("map_import");
  MapImportDef def;
  def.map = (src / "lot.svg").string();
  def.world = (dir / "lot.yaml").string();
  def.layers = {"Walls", "Obstacles"};
  const MapImport ref = importMap(def);
  EXPECT_EQ(ref.kind, "svg");
  EXPECT_NE(ref.text.find("map:\n  - {svg: \""), std::string::npos) << ref.text;
  EXPECT_EQ(ref.world.scenario.lot.x_max_m, 3.0);
  EXPECT_FALSE(placementProblem(ref.world.scenario, ref.world.scenario.start));
  EXPECT_GT(positionDistance(ref.world.scenario.start, ref.world.scenario.goal.pose), 2.0);
  // Written where the test says: the map's path is relative to that folder and loads from it.
  testing::writeText(def.world, ref.text);
  EXPECT_EQ(loadWorld(def.world).scenario.obstacles.size(), ref.world.scenario.obstacles.size());

  def.list_obstacles = true;
  const MapImport listed = importMap(def);
  EXPECT_EQ(listed.text.find("map:"), std::string::npos);
  EXPECT_NE(listed.text.find("holes:"), std::string::npos);  // the planter ring
  expectSameObstacles(ref.world.scenario, listed.world.scenario);

  // A map's cells written out: each merged rectangle as a polygon.
  def.map = (src / "lab.yaml").string();
  def.layers.clear();
  const MapImport cells = importMap(def);
  def.list_obstacles = false;
  expectSameObstacles(importMap(def).world.scenario, cells.world.scenario);
}

// A Moving AI maze of `cells` x `cells` with corridors and walls two cells wide (as the
// benchmark's maze-32-32-2) inside a wall two cells thick, carved by a seeded depth-first
// search.
std::string mazeText(int cells, unsigned seed) {
  const int rooms = (cells - 2) / 4;
  std::vector<std::string> rows(static_cast<std::size_t>(cells), std::string(cells, '@'));
  const auto open = [&](int x, int y) {  // a 2 x 2 block at cell (x, y)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx)
        rows[static_cast<std::size_t>(y + dy)][static_cast<std::size_t>(x + dx)] = '.';
  };
  std::mt19937 rng(seed);
  std::vector<bool> seen(static_cast<std::size_t>(rooms * rooms));
  std::vector<std::pair<int, int>> stack{{0, 0}};
  seen[0] = true;
  open(2, 2);
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    std::vector<std::pair<int, int>> next;
    for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int a = i + di;
      const int b = j + dj;
      if (a >= 0 && b >= 0 && a < rooms && b < rooms &&
          !seen[static_cast<std::size_t>(b * rooms + a)])
        next.emplace_back(a, b);
    }
    if (next.empty()) {
      stack.pop_back();
      continue;
    }
    const auto [a, b] = next[rng() % next.size()];
    seen[static_cast<std::size_t>(b * rooms + a)] = true;
    open(2 + 4 * a, 2 + 4 * b);
    open(2 + 2 * (i + a), 2 + 2 * (j + b));  // the wall between them
    stack.emplace_back(a, b);
  }
  std::string text = "type octile\nheight " + std::to_string(cells) + "\nwidth " +
                     std::to_string(cells) + "\nmap\n";
  for (const std::string& row : rows) text += row + "\n";
  return text;
}

// Regression (issue 39): free places were sought on an 80 x 80 lattice of the lot, which at
// 0.165 m cells falls on no place the maze's corridors leave the robot.
TEST(MapImport, FindsTheRoomAMazeHasAtAnyCellSize) {
  const fs::path dir = testing::freshDir("map_import_maze");
  testing::writeText(dir / "maze-32-32-2.map", mazeText(32, 5));
  MapImportDef def;
  def.map = (dir / "maze-32-32-2.map").string();
  def.world = (dir / "maze.yaml").string();
  for (const double cell : {0.16, 0.165, 0.17, 0.2, 0.5}) {
    def.cell_m = cell;
    const MapImport m = importMap(def);
    const Scenario& s = m.world.scenario;
    const double room = footprintRadius(s.robot);
    EXPECT_FALSE(placementProblem(s, s.start, room)) << cell;
    EXPECT_FALSE(placementProblem(s, s.goal.pose, room)) << cell;
    // From the corner corridors: more than half the lot's diagonal apart.
    EXPECT_GT(positionDistance(s.start, s.goal.pose), 0.5 * std::sqrt(2.0) * 32 * cell) << cell;
  }
}

// A room just larger than the footprint with its room, at an offset no lattice is tuned to.
TEST(MapImport, FindsTheOnlyPlaceThatFits) {
  const fs::path dir = testing::freshDir("map_import_pocket");
  const RobotDef robot;  // the import's robot
  const double room = footprintRadius(robot);
  // The footprint grown by its room, in 1 cm cells, and a little slack.
  const double cell = 0.01;
  const int w = static_cast<int>(std::ceil((robot.length_m + 2 * room) / cell)) + 2;
  const int h = static_cast<int>(std::ceil((robot.width_m + 2 * room) / cell)) + 2;
  std::string text = "type octile\nheight 100\nwidth 100\nmap\n";
  for (int r = 0; r < 100; ++r) {
    for (int c = 0; c < 100; ++c)
      text += r >= 41 && r < 41 + h && c >= 37 && c < 37 + w ? '.' : '@';
    text += "\n";
  }
  testing::writeText(dir / "pocket.map", text);
  MapImportDef def;
  def.map = (dir / "pocket.map").string();
  def.world = (dir / "pocket.yaml").string();
  def.cell_m = cell;
  const MapImport m = importMap(def);
  const Scenario& s = m.world.scenario;
  EXPECT_FALSE(placementProblem(s, s.start, room));
  // Inside the pocket (the map's first row is on top: rows 41.. from the top).
  EXPECT_GT(s.start.x, 0.37);
  EXPECT_LT(s.start.x, 0.37 + w * cell);
  EXPECT_GT(s.start.y, 1.0 - (41 + h) * cell);
  EXPECT_LT(s.start.y, 1.0 - 41 * cell);
}

TEST(MapImport, RefusesWhatItCannotImport) {
  const fs::path src = fs::path(testing::sourceDir()) / "worlds" / "maps";
  const auto errorOf = [](MapImportDef def) {
    try {
      (void)importMap(def);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  MapImportDef def;
  def.world = "w.yaml";
  def.map = "photo.jpg";
  EXPECT_EQ(errorOf(def),
            "photo.jpg: cannot tell the map's kind from its name: a ROS map server YAML (.yaml), "
            "an SVG drawing (.svg) or a Moving AI grid (.map)");
  def.map = (src / "warehouse.map").string();
  EXPECT_EQ(errorOf(def), def.map + ": a Moving AI grid has no cell size: give one (--cell, m)");
  // Every shape of the drawing, its page frame included: no room for the robot.
  def.map = (src / "lot.svg").string();
  EXPECT_EQ(errorOf(def).rfind("the map leaves no free place for parksim's default robot", 0), 0u);
  // Too many obstacles to write out: a noisy 300 x 300 grid.
  const fs::path dir = testing::freshDir("map_import_noise");
  std::mt19937_64 rng(9);
  std::vector<std::vector<int>> rows(300, std::vector<int>(300, 254));
  for (auto& row : rows) {
    for (int& v : row) v = rng() % 3 == 0 ? 0 : 254;
  }
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 20; ++i)
      rows[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] = 254;
  }
  testing::writePgm(dir / "noise.pgm", rows);
  testing::writeText(dir / "noise.yaml", "image: noise.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n");
  def.map = (dir / "noise.yaml").string();
  def.list_obstacles = true;
  EXPECT_NE(errorOf(def).find("beyond a world file's limits (10000 obstacles, 1 MiB): import it "
                              "as a map: reference instead"),
            std::string::npos)
      << errorOf(def);
}

}  // namespace
}  // namespace parksim
