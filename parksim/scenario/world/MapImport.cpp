#include "parksim/scenario/world/MapImport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/scenario/world/FreePlace.h"
#include "parksim/scenario/world/MapSection.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/scenario/yaml/YamlField.h"

namespace parksim {

namespace {

namespace fs = std::filesystem;

// A YAML double-quoted string: any path or name reads back as itself.
std::string yamlQuoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string num(double v) { return formatNumber(std::abs(v) < 5e-13 ? 0.0 : v); }

std::string briefNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string point(const Eigen::Vector2d& p) { return "[" + num(p.x()) + ", " + num(p.y()) + "]"; }

std::string ringText(const std::vector<Eigen::Vector2d>& ring) {
  std::string out = "[";
  for (std::size_t k = 0; k < ring.size(); ++k) out += (k ? ", " : "") + point(ring[k]);
  return out + "]";
}

std::string mapKind(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".yaml" || ext == ".yml") return "ros";
  if (ext == ".svg") return "svg";
  if (ext == ".map") return "movingai";
  throw Error(escapeText(path + ": cannot tell the map's kind from its name: a ROS map server "
                                "YAML (.yaml), an SVG drawing (.svg) or a Moving AI grid (.map)"));
}

// Two free places for the default robot, far apart: the free place nearest the lot's lower
// left for the start and the one nearest its upper right for the goal (FreePlace.h), keeping a
// footprint's radius of room around each.
std::pair<Pose2, Pose2> placeholders(const Scenario& s) {
  const double room = footprintRadius(s.robot);
  FreePlaceQuery query;
  query.room_m = room;
  const std::optional<Pose2> start = findFreePlace(s, query);
  if (!start) {
    throw Error("the map leaves no free place for parksim's default robot (" +
                formatNumber(s.robot.length_m) + " x " + formatNumber(s.robot.width_m) +
                " m with " + briefNumber(room) +
                " m of room); a drawing's frame or background may "
                "be among its shapes: select the obstacles' layers or ids");
  }
  query.from_upper_right = true;
  query.accept = [&](const Pose2& p) { return positionDistance(p, *start) > room; };
  if (const std::optional<Pose2> goal = findFreePlace(s, query)) return {*start, *goal};
  return {*start, {start->x, start->y, start->theta + kPi}};  // one free place: turn on it
}

// The obstacles as a world file writes them; a grid's rectangles each as a box.
std::string obstaclesText(const std::vector<Obstacle>& obstacles, std::size_t& count) {
  std::string out = "obstacles:\n";
  const auto head = [&](const std::string& name, const Obstacle& o) {
    ++count;
    return "  - {name: " + yamlQuoted(name) + ", kind: " + toString(o.kind) +
           ", height: " + num(o.height_m) + ", ";
  };
  for (const Obstacle& o : obstacles) {
    switch (o.shape) {
      case ObstacleShape::kBox:
        out += head(o.name, o) + "center: " + point(o.box.center) +
               ", size: " + point(2.0 * o.box.half_extents) +
               ", yaw_deg: " + num(radToDeg(o.box.yaw)) + "}\n";
        break;
      case ObstacleShape::kCircle:
        out += head(o.name, o) + "center: " + point(o.box.center) + ", radius: " + num(o.radius_m) +
               "}\n";
        break;
      case ObstacleShape::kPolygon:
        out += head(o.name, o) + "vertices: " + ringText(o.vertices) + "}\n";
        break;
      case ObstacleShape::kCompound: {
        const CompoundShape& c = *o.compound;
        // Outlines (counter-clockwise) each followed by their holes; without outlines (a map's
        // cells), the parts.
        std::vector<std::vector<const std::vector<Eigen::Vector2d>*>> polygons;
        for (const auto& ring : c.rings) {
          if (signedDoubleArea(ring) > 0.0 || polygons.empty()) polygons.emplace_back();
          polygons.back().push_back(&ring);
        }
        if (polygons.empty()) {
          for (const auto& part : c.parts) polygons.push_back({&part});
        }
        for (std::size_t k = 0; k < polygons.size(); ++k) {
          const std::string name = polygons.size() == 1 ? o.name : o.name + "/" + std::to_string(k);
          out += head(name, o) + "vertices: " + ringText(*polygons[k][0]);
          if (polygons[k].size() > 1) {
            out += ", holes: [";
            for (std::size_t h = 1; h < polygons[k].size(); ++h) {
              out += (h > 1 ? ", " : "") + ringText(*polygons[k][h]);
            }
            out += "]";
          }
          out += "}\n";
        }
        break;
      }
    }
  }
  return out;
}

}  // namespace

MapImport importMap(const MapImportDef& def) {
  MapImport out;
  out.kind = mapKind(def.map);
  const fs::path world_dir = fs::absolute(fs::path(def.world)).parent_path();
  std::string rel =
      fs::absolute(fs::path(def.map)).lexically_normal().lexically_relative(world_dir).string();
  if (rel.empty()) rel = fs::absolute(def.map).lexically_normal().string();
  std::string entry = "{" + out.kind + ": " + yamlQuoted(rel);
  if (out.kind == "movingai") {
    if (!def.cell_m) {
      throw Error(
          escapeText(def.map + ": a Moving AI grid has no cell size: give one (--cell, m)"));
    }
    entry += ", cell: " + num(*def.cell_m);
  }
  if (out.kind == "svg" && def.scale) entry += ", scale: " + num(*def.scale);
  for (const auto& [key, names] : {std::pair{"layers", &def.layers}, std::pair{"ids", &def.ids}}) {
    if (names->empty()) continue;
    if (out.kind != "svg")
      throw Error(std::string(key) + " select the shapes of SVG drawings only");
    entry += std::string(", ") + key + ": [";
    for (std::size_t k = 0; k < names->size(); ++k)
      entry += (k ? ", " : "") + yamlQuoted((*names)[k]);
    entry += "]";
  }
  entry += "}";

  // The map's obstacles and extent, read as the world will read them.
  const YAML::Node list = YAML::Load("[" + entry + "]");
  const MapSection maps = readMapSection(YamlField(list, "map", 0, ""), def.world);
  Scenario probe;
  probe.obstacles = maps.obstacles;
  probe.lot = {maps.extent.min().x(), maps.extent.min().y(), maps.extent.max().x(),
               maps.extent.max().y()};
  const auto [start, goal] = placeholders(probe);

  std::string name = fs::path(def.map).stem().string();
  if (name.empty() || !isPrintableUtf8(name)) name = "map";
  std::string& t = out.text;
  t = "# Imported from " + escapeText(def.map) +
      " by `parksim import` (docs/world-format.md, "
      "\"Maps\").\n# The lot's bounds are the map's extent. The robot is parksim's default, and "
      "start and goal\n# are two free places the import found, far apart: edit them for your "
      "problem.\nformat: parksim-world/1\nname: " +
      yamlQuoted(name) + "\n";
  if (def.list_obstacles) {
    std::size_t count = 0;
    t += "lot: {x_min: " + num(probe.lot.x_min_m) + ", y_min: " + num(probe.lot.y_min_m) +
         ", x_max: " + num(probe.lot.x_max_m) + ", y_max: " + num(probe.lot.y_max_m) + "}\n";
    t += obstaclesText(maps.obstacles, count);
    if (count > kMaxObstacles || t.size() > kMaxWorldFileBytes / 2) {
      throw Error(escapeText(def.map + ": written out, the map makes " + std::to_string(count) +
                             " obstacles in " + std::to_string(t.size()) +
                             " bytes, beyond a world file's limits (" +
                             std::to_string(kMaxObstacles) +
                             " obstacles, 1 MiB): import it as a map: reference instead"));
    }
  } else {
    t += "map:\n  - " + entry + "\n";
  }
  t += "# robot: {length: 0.08, width: 0.085, front_overhang: 0.01, wheel_base: 0.085}\n";
  t += "start: [" + num(start.x) + ", " + num(start.y) + ", " + num(radToDeg(start.theta)) + "]\n";
  t += "goal:\n  pose: [" + num(goal.x) + ", " + num(goal.y) + ", " + num(radToDeg(goal.theta)) +
       "]\n";
  out.world = parseWorld(t, def.world);
  out.warnings = maps.warnings;
  return out;
}

}  // namespace parksim
