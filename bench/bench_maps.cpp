// Maps in worlds (issue 32), each against a baseline run side by side (docs/benchmarks.md,
// "Maps"):
// - a 1,000 x 1,000-cell ROS map (a 50 x 50 m warehouse at 5 cm: walls, shelf rows, pillars and
//   2,000 specks of noise) read, merged into rectangles and put into Bullet (the planner's
//   collision world and the dynamics world's bodies), against the same rectangles written by
//   hand as box obstacles in a world file;
// - the same map planned with the default setup between opposite free corners, against the
//   hand-written lot;
// - the 30 x 15 m warehouse (worlds/warehouse.yaml) planned with the default setup;
// - an SVG drawing of 500 shapes (rectangles, circles, rotated groups, L-shaped paths) read,
//   against the same shapes written by hand as boxes, circles and polygons.
// The files are made once per run in a temporary folder.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/geometry/GridRectangles.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/scenario/world/World.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

constexpr int kSide = 1000;
constexpr double kCell = 0.05;
const char* const kRobot =
    "robot: {length: 0.3, width: 0.3, front_overhang: 0.1, wheel_base: 0.28, wheel_radius: 0.033, "
    "max_wheel_speed_radps: 7.9, max_wheel_accel_radps2: 20, height: 0.14}\n"
    "physics: {chassis_mass_kg: 1.8, wheel_mass_kg: 0.03, max_wheel_torque_nm: 1.5}\n";
const char* const kStartGoal =
    "start: [1.0, 1.0, 0]\ngoal: {pose: [49.0, 49.0, 90], position_tolerance: 0.005}\n";

// A temporary folder for the run's files, removed at exit.
struct TempFolder {
  fs::path path = fs::temp_directory_path() / ("parksim-bench-maps-" + std::to_string(::getpid()));
  TempFolder() { fs::create_directories(path); }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

fs::path folder() {
  static const TempFolder dir;
  return dir.path;
}

// The 1,000 x 1,000 map's cells (1 occupied), rows from the bottom.
std::vector<std::uint8_t> warehouseCells() {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(kSide * kSide), 0);
  const auto block = [&](int i0, int j0, int i1, int j1) {
    for (int j = j0; j < j1; ++j) {
      for (int i = i0; i < i1; ++i) cells[static_cast<std::size_t>(j * kSide + i)] = 1;
    }
  };
  block(0, 0, kSide, 4);
  block(0, kSide - 4, kSide, kSide);
  block(0, 0, 4, kSide);
  block(kSide - 4, 0, kSide, kSide);
  for (int row = 0; row < 14; ++row) {  // shelf rows 1 m deep with 2.5 m aisles
    for (int col = 0; col < 4; ++col) {
      block(80 + col * 220, 60 + row * 64, 80 + col * 220 + 180, 60 + row * 64 + 20);
    }
  }
  for (int k = 0; k < 40; ++k) block(40 + 23 * k, 40, 48 + 23 * k, 48);  // a row of pillars
  std::mt19937_64 rng(32);
  std::uniform_int_distribution<int> at(10, kSide - 10);
  for (int k = 0; k < 2000; ++k) {  // noise: single cells in the aisles
    const int i = at(rng);
    const int j = at(rng);
    if (i > 30 || j > 30) cells[static_cast<std::size_t>(j * kSide + i)] = 1;
    if (i > kSide - 31 && j > kSide - 31) cells[static_cast<std::size_t>(j * kSide + i)] = 0;
  }
  for (int j = 0; j < 40; ++j) {  // free corners for the start and the goal
    for (int i = 0; i < 40; ++i) {
      if (i >= 4 && j >= 4) cells[static_cast<std::size_t>(j * kSide + i)] = 0;
      if (i >= 4 && j >= 4) {
        cells[static_cast<std::size_t>((kSide - 1 - j) * kSide + (kSide - 1 - i))] = 0;
      }
    }
  }
  return cells;
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The map world and the hand-written world of the same rectangles, made once.
struct GridFiles {
  fs::path map_world;
  fs::path box_world;
  std::size_t rectangles = 0;
};

const GridFiles& gridFiles() {
  static const GridFiles files = [] {
    GridFiles f;
    const std::vector<std::uint8_t> cells = warehouseCells();
    std::string pgm = "P5\n" + std::to_string(kSide) + " " + std::to_string(kSide) + "\n255\n";
    for (int r = 0; r < kSide; ++r) {
      const int j = kSide - 1 - r;
      for (int i = 0; i < kSide; ++i)
        pgm += cells[static_cast<std::size_t>(j * kSide + i)] ? '\0' : '\xfe';
    }
    writeFile(folder() / "wh.pgm", pgm);
    writeFile(folder() / "wh.yaml", "image: wh.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
    f.map_world = folder() / "map_world.yaml";
    writeFile(f.map_world,
              std::string("format: parksim-world/1\nname: grid\nmap: [{ros: wh.yaml}]\n") + kRobot +
                  kStartGoal);
    std::ostringstream boxes;
    boxes.precision(17);
    boxes
        << "format: parksim-world/1\nname: boxes\nlot: {x_min: 0, y_min: 0, x_max: 50, y_max: 50}\n"
        << kRobot << kStartGoal << "obstacles:\n";
    const std::vector<CellRect> rects = mergeCells(cells, kSide, kSide);
    f.rectangles = rects.size();
    int n = 0;
    for (const CellRect& r : rects) {
      boxes << "  - {name: b" << n++ << ", kind: wall, center: [" << 0.5 * (r.i0 + r.i1) * kCell
            << ", " << 0.5 * (r.j0 + r.j1) * kCell << "], size: [" << (r.i1 - r.i0) * kCell << ", "
            << (r.j1 - r.j0) * kCell << "]}\n";
    }
    f.box_world = folder() / "box_world.yaml";
    writeFile(f.box_world, boxes.str());
    return f;
  }();
  return files;
}

// Read, merged, in both Bullet worlds: what a command does before it plans.
void loadIntoBullet(benchmark::State& state, const fs::path& world_file) {
  for (auto _ : state) {
    const World w = loadWorld(world_file.string());
    const BulletCollisionWorld collision(w.scenario);
    const DynamicsWorld dynamics(w.scenario, w.scenario.start);
    benchmark::DoNotOptimize(collision.obstacleCount());
  }
  state.counters["rectangles"] = static_cast<double>(gridFiles().rectangles);
}

void BM_GridMapLoad1000(benchmark::State& state) { loadIntoBullet(state, gridFiles().map_world); }
void BM_HandWrittenLotLoad(benchmark::State& state) {
  loadIntoBullet(state, gridFiles().box_world);
}

void planWorld(benchmark::State& state, const fs::path& world_file) {
  const World w = loadWorld(world_file.string());
  const BulletCollisionWorld collision(w.scenario);
  PlanResult last;
  for (auto _ : state) last = planScenario(w.scenario, collision, PlanSetup{});
  if (!last.solved()) state.SkipWithError("not solved");
  state.counters["expansions"] = last.stats.iterations;
  state.counters["budget"] = resolvedPlanSetup(PlanSetup{}, w.scenario).search.max_iterations;
}

void BM_GridMapPlan1000(benchmark::State& state) { planWorld(state, gridFiles().map_world); }
void BM_HandWrittenLotPlan(benchmark::State& state) { planWorld(state, gridFiles().box_world); }
// The source tree, from the build tree this program lives in (BUILD/bench/bench_maps).
fs::path sourceTree() {
  if (std::getenv("PARKSIM_SOURCE_DIR") == nullptr &&
      std::getenv("PARKSIM_BINARY_DIR") == nullptr) {
    const fs::path build = fs::read_symlink("/proc/self/exe").parent_path().parent_path();
    ::setenv("PARKSIM_BINARY_DIR", build.c_str(), 0);
  }
  return testing::sourceDir();
}

void BM_WarehousePlan(benchmark::State& state) {
  planWorld(state, sourceTree() / "worlds" / "warehouse.yaml");
}

// 500 shapes in a 10 x 10 m drawing: rectangles, circles, L-shaped paths and rotated groups.
struct SvgFiles {
  fs::path svg_world;
  fs::path yaml_world;
};

const SvgFiles& svgFiles() {
  static const SvgFiles files = [] {
    std::ostringstream svg;
    std::ostringstream yaml;
    yaml.precision(17);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10000mm\" height=\"10000mm\" "
           "viewBox=\"0 0 10000 10000\">\n";
    yaml << "format: parksim-world/1\nname: shapes\nlot: {x_min: 0, y_min: 0, x_max: 10, y_max: "
            "10}\nstart: [0.05, 0.05, 0]\ngoal: {pose: [0.05, 0.1, 0]}\nobstacles:\n";
    for (int k = 0; k < 500; ++k) {
      const int gx = 200 + (k % 25) * 380;
      const int gy = 400 + (k / 25) * 480;
      const double lx = gx / 1000.0;
      const double ly = 10.0 - gy / 1000.0;
      switch (k % 4) {
        case 0:
          svg << "<rect id=\"s" << k << "\" x=\"" << gx << "\" y=\"" << gy
              << "\" width=\"200\" height=\"100\"/>\n";
          yaml << "  - {name: s" << k << ", kind: box, center: [" << lx + 0.1 << ", " << ly - 0.05
               << "], size: [0.2, 0.1]}\n";
          break;
        case 1:
          svg << "<circle id=\"s" << k << "\" cx=\"" << gx << "\" cy=\"" << gy << "\" r=\"60\"/>\n";
          yaml << "  - {name: s" << k << ", kind: bollard, center: [" << lx << ", " << ly
               << "], radius: 0.06}\n";
          break;
        case 2:
          svg << "<path id=\"s" << k << "\" d=\"M " << gx << "," << gy
              << " h 200 v 60 h -140 v 140 h -60 Z\"/>\n";
          yaml << "  - {name: s" << k << "a, kind: wall, vertices: [[" << lx << ", " << ly << "], ["
               << lx + 0.2 << ", " << ly << "], [" << lx + 0.2 << ", " << ly - 0.06 << "], [" << lx
               << ", " << ly - 0.06 << "]]}\n"
               << "  - {name: s" << k << "b, kind: wall, vertices: [[" << lx << ", " << ly - 0.06
               << "], [" << lx + 0.06 << ", " << ly - 0.06 << "], [" << lx + 0.06 << ", "
               << ly - 0.2 << "], [" << lx << ", " << ly - 0.2 << "]]}\n";
          break;
        default:
          svg << "<g transform=\"translate(" << gx << "," << gy << ") rotate(30)\"><rect id=\"s"
              << k << "\" x=\"-100\" y=\"-40\" width=\"200\" height=\"80\"/></g>\n";
          yaml << "  - {name: s" << k << ", kind: box, center: [" << lx << ", " << ly
               << "], size: [0.2, 0.08], yaw_deg: -30}\n";
      }
    }
    svg << "</svg>\n";
    SvgFiles f;
    writeFile(folder() / "shapes.svg", svg.str());
    f.svg_world = folder() / "svg_world.yaml";
    writeFile(f.svg_world,
              "format: parksim-world/1\nname: shapes\nmap: [{svg: shapes.svg}]\n"
              "start: [0.05, 0.05, 0]\ngoal: {pose: [0.05, 0.1, 0]}\n");
    f.yaml_world = folder() / "yaml_world.yaml";
    writeFile(f.yaml_world, yaml.str());
    return f;
  }();
  return files;
}

void readWorld(benchmark::State& state, const fs::path& world_file) {
  std::size_t obstacles = 0;
  for (auto _ : state) obstacles = loadWorld(world_file.string()).scenario.obstacles.size();
  state.counters["obstacles"] = static_cast<double>(obstacles);
}

void BM_SvgRead500(benchmark::State& state) { readWorld(state, svgFiles().svg_world); }
void BM_HandWrittenShapesRead(benchmark::State& state) { readWorld(state, svgFiles().yaml_world); }

BENCHMARK(BM_GridMapLoad1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HandWrittenLotLoad)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridMapPlan1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HandWrittenLotPlan)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WarehousePlan)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SvgRead500)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HandWrittenShapesRead)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace parksim
