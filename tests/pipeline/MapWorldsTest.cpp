// The map worlds of issue 32, end to end: a ROS map server world plans, runs and renders, and
// its plan keeps the footprint off every occupied and unknown cell of the image (checked here
// over the image itself, with its own geometry, not through parksim's collision code); an SVG
// lot with non-convex shapes and transforms plans and runs, and its obstacles are drawn where
// the SVG draws them; a floor plan whose walls are drawn as lines (two-point paths and
// polylines, a closed path on one line, a line) plans around every wall, checked against the
// lines themselves; the Moving AI warehouse plans with the default setup.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "parksim/scenario/world/World.h"
#include "tests/support/MapFiles.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<const World> world(const std::string& name) {
  return std::make_shared<const World>(
      loadWorld((fs::path(testing::sourceDir()) / "worlds" / (name + ".yaml")).string()));
}

// --- The image, read here: P5 header, thresholds from the map's YAML. ---
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;  // rows from the top
};

Image readPgm(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  Image img;
  int max_value = 0;
  in >> magic;
  // Skip the comment line map_saver-style files carry.
  in >> std::ws;
  while (in.peek() == '#') in.ignore(1 << 20, '\n');
  in >> img.width >> img.height >> max_value;
  in.get();
  img.pixels.resize(static_cast<std::size_t>(img.width * img.height));
  in.read(reinterpret_cast<char*>(img.pixels.data()),
          static_cast<std::streamsize>(img.pixels.size()));
  EXPECT_EQ(magic, "P5");
  EXPECT_EQ(max_value, 255);
  return img;
}

// Signed gap between an axis-aligned square and a rectangle (centre, half sizes, heading) along
// the four axes of the two: > 0 apart, <= 0 touching or overlapping.
double gapSquareRect(double x0, double y0, double side, const Eigen::Vector2d& c, double hl,
                     double hw, double yaw) {
  const Eigen::Vector2d u(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d v(-u.y(), u.x());
  const Eigen::Vector2d s(x0 + 0.5 * side, y0 + 0.5 * side);
  double gap = -1e300;
  for (const Eigen::Vector2d& axis : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1), u, v}) {
    const double rect = hl * std::abs(axis.dot(u)) + hw * std::abs(axis.dot(v));
    const double square = 0.5 * side * (std::abs(axis.x()) + std::abs(axis.y()));
    gap = std::max(gap, std::abs(axis.dot(s - c)) - rect - square);
  }
  return gap;
}

TEST(MapWorlds, TheRosLabPlansRunsRendersAndItsPlanKeepsOffEveryOccupiedAndUnknownCell) {
  EpisodeRequest request;
  request.world = world("ros_lab");
  const fs::path out = testing::testOutputDir("map_worlds_ros");
  fs::remove_all(out);
  request.out_dir = out.string();
  request.figures.figures = FigureSelection::parse("lot_map");
  const EpisodeOutcome outcome = runEpisodePipeline(request);
  ASSERT_EQ(outcome.verdict.status, EpisodeStatus::kMet) << outcome.verdict.reason;
  EXPECT_GT(fs::file_size(out / "figures" / "lot_map.png"), 1000u);

  const fs::path maps = fs::path(testing::sourceDir()) / "worlds" / "maps";
  const YAML::Node yaml = YAML::LoadFile((maps / "lab.yaml").string());
  const double res = yaml["resolution"].as<double>();
  const double ox = yaml["origin"][0].as<double>();
  const double oy = yaml["origin"][1].as<double>();
  ASSERT_EQ(yaml["origin"][2].as<double>(), 0.0);
  const double free_thresh = yaml["free_thresh"].as<double>();
  const Image img = readPgm(maps / yaml["image"].as<std::string>());
  // Occupied or unknown: every pixel whose occupancy is not below free_thresh.
  std::vector<char> blocked(img.pixels.size());
  int blocked_count = 0;
  for (std::size_t k = 0; k < img.pixels.size(); ++k) {
    blocked[k] = 1.0 - img.pixels[k] / 255.0 >= free_thresh;
    blocked_count += blocked[k];
  }
  ASSERT_GT(blocked_count, 1000);

  const RobotDef& robot = request.world->scenario.robot;
  const double hl = 0.5 * robot.length_m;
  const double hw = 0.5 * robot.width_m;
  const double ahead = robot.front_overhang_m - hl;  // reference point to footprint centre
  const auto& points = outcome.trajectory.points;
  ASSERT_GT(points.size(), 10u);
  double closest = 1e300;
  long poses = 0;
  for (std::size_t n = 0; n + 1 < points.size(); ++n) {
    const Pose2 a = points[n].pose;
    const Pose2 b = points[n + 1].pose;
    const int steps = 1 + static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 0.0005 +
                                           std::abs(b.theta - a.theta) / 0.005);
    for (int s = 0; s < steps; ++s) {
      const double t = double(s) / steps;
      const double x = a.x + t * (b.x - a.x);
      const double y = a.y + t * (b.y - a.y);
      const double yaw = a.theta + t * (b.theta - a.theta);
      const Eigen::Vector2d c(x + ahead * std::cos(yaw), y + ahead * std::sin(yaw));
      const double reach = std::hypot(hl, hw) + 2 * res;
      const int i0 = std::max(0, static_cast<int>(std::floor((c.x() - reach - ox) / res)));
      const int i1 =
          std::min(img.width - 1, static_cast<int>(std::floor((c.x() + reach - ox) / res)));
      const int j0 = std::max(0, static_cast<int>(std::floor((c.y() - reach - oy) / res)));
      const int j1 =
          std::min(img.height - 1, static_cast<int>(std::floor((c.y() + reach - oy) / res)));
      for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
          const int row = img.height - 1 - j;  // the image's first row is the map's top
          if (!blocked[static_cast<std::size_t>(row * img.width + i)]) continue;
          const double gap = gapSquareRect(ox + i * res, oy + j * res, res, c, hl, hw, yaw);
          ASSERT_GE(gap, 0.0) << "pose " << x << ", " << y << ", " << yaw << " meets cell " << i
                              << ", " << j;
          closest = std::min(closest, gap);
        }
      }
      ++poses;
    }
  }
  EXPECT_GT(poses, 5000);
  // The bay holds the robot a few centimetres from its dividers and wall: the check bites.
  EXPECT_LT(closest, 0.05);
}

// A lot point is drawn as an obstacle when some box or prism of the scene covers it.
bool drawnAt(const Scene& scene, const Eigen::Vector2d& p) {
  const auto inside = [&](const auto& polygon) {
    const std::size_t n = polygon.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d e = polygon[(k + 1) % n] - polygon[k];
      const Eigen::Vector2d d = p - polygon[k];
      if (e.x() * d.y() - e.y() * d.x() < 0.0) return false;
    }
    return true;
  };
  for (const SceneBox& b : scene.boxes) {
    if (inside(b.footprint.corners())) return true;
  }
  for (const ScenePrism& prism : scene.prisms) {
    if (inside(prism.footprint)) return true;
  }
  return false;
}

TEST(MapWorlds, TheSvgLotPlansRunsAndDrawsItsObstaclesWhereTheSvgDoes) {
  EpisodeRequest request;
  request.world = world("svg_lot");
  const EpisodeOutcome outcome = runEpisodePipeline(request);
  ASSERT_EQ(outcome.verdict.status, EpisodeStatus::kMet) << outcome.verdict.reason;
  const Scene scene = buildLotScene(request.world->scenario, SceneStyle{});
  // Points from worlds/maps/lot.svg: page (u, v) mm lies at lot (u / 1000, 2 - v / 1000) m.
  const auto lot = [](double u, double v) { return Eigen::Vector2d(u / 1000.0, 2.0 - v / 1000.0); };
  struct Probe {
    Eigen::Vector2d at;
    bool drawn;
    const char* what;
  };
  const Probe probes[] = {
      {lot(1700, 1400), true, "bollard_1's centre"},
      {lot(1735, 1400), false, "just beyond bollard_1's 30 mm radius"},
      {lot(1000, 1000), false, "the planter ring's hole"},
      {lot(1180, 1000), true, "the planter ring"},
      {lot(1260, 1000), false, "beyond the planter ring"},
      {lot(2380, 1690), true, "the parked car's body"},
      {lot(2590, 1650), true, "the car's right mirror"},
      {lot(2590, 1700), false, "behind the car's mirror"},
      {lot(2800, 1275), true, "the L-shaped wall's arm"},
      {lot(2800, 1200), false, "above the wall's arm"},
      {lot(2041.5, 245.1), true, "divider_2 in the rotated group"},
      {lot(1990, 250), false, "the bay between divider_1 and divider_2"},
      {lot(600, 1535), true, "the curved kerb"},
      {lot(60, 1800), false, "the Notes layer's page frame (not selected)"},
  };
  for (const Probe& p : probes) EXPECT_EQ(drawnAt(scene, p.at), p.drawn) << p.what;
}

// --- A floor plan drawn with walls as lines, and its geometry computed here. ---
struct LineWall {
  std::string element;   // how it is drawn: path, polyline, closed (a closed path), line
  Eigen::Vector2d a, b;  // page mm, y down
};

std::string svgElement(const LineWall& w) {
  const auto xy = [](const Eigen::Vector2d& p) {
    return std::to_string(p.x()) + "," + std::to_string(p.y());
  };
  if (w.element == "path") return "<path d=\"M " + xy(w.a) + " L " + xy(w.b) + "\"/>";
  if (w.element == "polyline") return "<polyline points=\"" + xy(w.a) + " " + xy(w.b) + "\"/>";
  if (w.element == "closed") {
    // There, back past the middle, and closed: a closed path on one line.
    return "<path d=\"M " + xy(w.a) + " L " + xy(w.b) + " L " + xy(0.5 * (w.a + w.b)) + " Z\"/>";
  }
  return "<line x1=\"" + std::to_string(w.a.x()) + "\" y1=\"" + std::to_string(w.a.y()) +
         "\" x2=\"" + std::to_string(w.b.x()) + "\" y2=\"" + std::to_string(w.b.y()) + "\"/>";
}

// Distance from the rectangle (centre c, half sizes hl x hw, heading yaw) to the segment pq:
// 0 when they meet.
double rectSegmentDistance(const Eigen::Vector2d& c, double hl, double hw, double yaw,
                           const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  const Eigen::Vector2d u(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d v(-u.y(), u.x());
  const auto toRect = [&](const Eigen::Vector2d& x) {
    const Eigen::Vector2d d = x - c;
    return std::hypot(std::max(0.0, std::abs(d.dot(u)) - hl),
                      std::max(0.0, std::abs(d.dot(v)) - hw));
  };
  const auto toSegment = [&](const Eigen::Vector2d& x) {
    const Eigen::Vector2d e = q - p;
    const double t = std::clamp((x - p).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p + t * e - x).norm();
  };
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  const Eigen::Vector2d corners[] = {c + hl * u + hw * v, c - hl * u + hw * v, c - hl * u - hw * v,
                                     c + hl * u - hw * v};
  double best = std::min(toRect(p), toRect(q));
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& r = corners[k];
    const Eigen::Vector2d& s = corners[(k + 1) % 4];
    best = std::min(best, toSegment(r));
    const bool crosses = cross(s - r, p - r) * cross(s - r, q - r) < 0.0 &&
                         cross(q - p, r - p) * cross(q - p, s - p) < 0.0;
    if (crosses) best = 0.0;
  }
  return best;
}

TEST(MapWorlds, AFloorPlanDrawnWithLinesPlansAroundEveryWall) {
  // 1300 x 800 mm: outer walls, a partition, and a U-shaped alcove (open to the east) holding
  // the goal, straight east of the start: the way in is round the alcove, not through it.
  const double width_mm = 20.0;
  const std::vector<LineWall> walls = {
      {"path", {10, 10}, {1290, 10}},        {"path", {1290, 10}, {1290, 790}},
      {"path", {1290, 790}, {10, 790}},      {"path", {10, 790}, {10, 10}},
      {"line", {400, 10}, {400, 300}},       {"path", {800, 250}, {800, 550}},
      {"polyline", {800, 250}, {1050, 250}}, {"closed", {800, 550}, {1050, 550}},
  };
  std::string svg =
      "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1300mm\" "
      "height=\"800mm\" viewBox=\"0 0 1300 800\">\n"
      "<g id=\"walls\" style=\"fill:none;stroke:#000;stroke-width:" +
      std::to_string(width_mm) + "\">\n";
  for (const LineWall& w : walls) svg += svgElement(w) + "\n";
  svg +=
      "</g>\n<rect id=\"table\" x=\"150\" y=\"600\" width=\"150\" height=\"100\"/>\n"
      "<circle id=\"pillar\" cx=\"600\" cy=\"150\" r=\"30\"/>\n</svg>\n";
  const fs::path dir = testing::freshDir("map_worlds_floor_plan");
  testing::writeText(dir / "plan.svg", svg);
  testing::writeText(dir / "floor_plan.yaml",
                     "format: parksim-world/1\nname: floor_plan\n"
                     "lot: {x_min: 0.0, y_min: 0.0, x_max: 1.3, y_max: 0.8}\n"
                     "map:\n  - {svg: plan.svg, name: plan, height: 0.1}\n"
                     "start: [0.2, 0.4, 0]\n"
                     "goal: {pose: [0.95, 0.4, 180], position_tolerance: 0.002, "
                     "heading_tolerance_deg: 1}\n");
  EpisodeRequest request;
  request.world = std::make_shared<const World>(loadWorld((dir / "floor_plan.yaml").string()));
  // Every wall and both pieces of furniture: nothing drawn is dropped.
  EXPECT_EQ(request.world->scenario.obstacles.size(), walls.size() + 2);
  request.drive = false;
  const EpisodeOutcome outcome = runEpisodePipeline(request);
  ASSERT_TRUE(outcome.plan && outcome.plan->solved()) << outcome.verdict.reason;

  // Every pose of the plan, 0.5 mm and 0.005 rad apart, keeps the footprint more than half a
  // wall's width from each wall's line (in the lot: x = u / 1000, y = 0.8 - v / 1000).
  const RobotDef& robot = request.world->scenario.robot;
  const double hl = 0.5 * robot.length_m;
  const double hw = 0.5 * robot.width_m;
  const double ahead = robot.front_overhang_m - hl;
  const auto lot = [](const Eigen::Vector2d& page) {
    return Eigen::Vector2d(page.x() / 1000.0, 0.8 - page.y() / 1000.0);
  };
  const auto& points = outcome.plan->trajectory.points;
  ASSERT_GT(points.size(), 10u);
  double closest = 1e300;
  for (std::size_t n = 0; n + 1 < points.size(); ++n) {
    const Pose2 a = points[n].pose;
    const Pose2 b = points[n + 1].pose;
    const int steps = 1 + static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 0.0005 +
                                           std::abs(b.theta - a.theta) / 0.005);
    for (int s = 0; s < steps; ++s) {
      const double t = double(s) / steps;
      const double yaw = a.theta + t * (b.theta - a.theta);
      const Eigen::Vector2d c(a.x + t * (b.x - a.x) + ahead * std::cos(yaw),
                              a.y + t * (b.y - a.y) + ahead * std::sin(yaw));
      for (const LineWall& w : walls) {
        const double gap = rectSegmentDistance(c, hl, hw, yaw, lot(w.a), lot(w.b));
        ASSERT_GT(gap, 0.5 * width_mm / 1000.0)
            << "the footprint at " << c.transpose() << ", " << yaw << " meets the " << w.element
            << " wall from " << w.a.transpose() << " to " << w.b.transpose() << " (page mm)";
        closest = std::min(closest, gap - 0.5 * width_mm / 1000.0);
      }
    }
  }
  // Round the alcove and into it: the plan comes within a few centimetres of its walls.
  EXPECT_LT(closest, 0.05);
}

TEST(MapWorlds, TheWarehousePlansWithTheDefaults) {
  EpisodeRequest request;
  request.world = world("warehouse");
  request.drive = false;
  const EpisodeOutcome outcome = runEpisodePipeline(request);
  ASSERT_TRUE(outcome.plan && outcome.plan->solved()) << outcome.verdict.reason;
  EXPECT_GT(outcome.plan->trajectory.duration(), 60.0);  // 30 m at 0.2 m/s
}

}  // namespace
}  // namespace parksim
