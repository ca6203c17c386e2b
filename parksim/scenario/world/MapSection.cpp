#include "parksim/scenario/world/MapSection.h"

#include <filesystem>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Fnv1a.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/scenario/maps/GridMap.h"
#include "parksim/scenario/maps/MapLimits.h"
#include "parksim/scenario/maps/MovingAiMap.h"
#include "parksim/scenario/maps/RosMap.h"
#include "parksim/scenario/maps/SvgMap.h"
#include "parksim/scenario/world/WorldDocument.h"

namespace parksim {

namespace {

// A map file named by the world, relative to the world file's folder.
std::string besideWorld(const std::string& world_source, const std::string& file) {
  const std::filesystem::path p(file);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (std::filesystem::path(world_source).parent_path() / p).lexically_normal().string();
}

// FNV-1a of the map's files: an edited map changes the world's content hash.
std::uint64_t hashFiles(const std::vector<std::string>& files, std::uintmax_t max_bytes) {
  std::uint64_t h = fnv1a64("");
  for (const std::string& f : files) h = fnv1a64(readInputFile(f, max_bytes, "map file"), h);
  return h;
}

Eigen::Vector2d readOrigin(const std::optional<YamlField>& f) {
  if (!f) return Eigen::Vector2d::Zero();
  f->numbers(2, "[x, y]");
  const std::vector<YamlField> xy = f->items();
  return {xy[0].inRange(-1e4, 1e4, " m"), xy[1].inRange(-1e4, 1e4, " m")};
}

Eigen::AlignedBox2d boundsOf(const std::array<Eigen::Vector2d, 4>& corners) {
  Eigen::AlignedBox2d b;
  b.setEmpty();
  for (const Eigen::Vector2d& c : corners) b.extend(c);
  return b;
}

struct EntryCommon {
  std::string name;
  ObstacleKind kind = ObstacleKind::kWall;
  double height_m = 0.1;
};

EntryCommon readCommon(const YamlMap& m, const std::string& file) {
  EntryCommon c;
  c.name =
      m.optional("name") ? m.optional("name")->name() : std::filesystem::path(file).stem().string();
  if (c.name.empty()) c.name = "map";
  if (const auto f = m.optional("kind")) c.kind = readObstacleKind(*f);
  if (const auto f = m.optional("height")) {
    c.height_m = f->positive();
    if (c.height_m > 1e4) f->fail("must be at most 10000 m, got " + f->node().Scalar());
  }
  return c;
}

double readInflation(const YamlMap& m) {
  const auto f = m.optional("inflation");
  return f ? f->inRange(0.0, 100.0, " m") : 0.0;
}

// Runs a map reader; its error (which names the map file) becomes the entry field's message.
template <typename F>
auto located(const YamlField& at, F&& read) {
  try {
    return read();
  } catch (const Error& e) {
    at.fail(e.what());
  }
}

void addGrid(MapSection& out, const YamlField& at, std::shared_ptr<const OccupancyGrid> grid,
             const GridMapDef& def, std::uint64_t hash) {
  const Eigen::AlignedBox2d extent = boundsOf(grid->extent());
  GridMapObstacles g = located(at, [&] { return gridMapObstacles(std::move(grid), def); });
  g.layer.content_hash = hex16(hash);
  if (g.obstacle) out.obstacles.push_back(std::move(*g.obstacle));
  out.layers.push_back(std::move(g.layer));
  out.extent.extend(extent);
}

void readRosEntry(MapSection& out, const YamlField& entry, const std::string& world) {
  const YamlMap m =
      entry.map({"ros", "name", "kind", "height", "unknown", "inflation", "lethal_threshold"});
  const YamlField file_field = m.required("ros");
  const std::string file = besideWorld(world, file_field.text());
  const EntryCommon common = readCommon(m, file);
  int lethal = 100;
  if (const auto f = m.optional("lethal_threshold")) {
    lethal = f->positiveInt();
    if (lethal > 100) f->fail("must be in [1, 100], got " + f->node().Scalar());
  }
  GridMapDef def{common.name, file, common.kind, common.height_m, true, readInflation(m)};
  if (const auto f = m.optional("unknown")) {
    const std::string s = f->text();
    if (s != "occupied" && s != "free") {
      f->fail("must be occupied or free, got \"" + s + "\"");
    }
    def.unknown_blocks = s == "occupied";
  }
  std::vector<std::string> warnings;
  auto grid = located(file_field, [&] { return readRosMap(file, lethal, &warnings); });
  // The image's name comes from the YAML, which the reader has just checked.
  const YAML::Node yaml = YAML::Load(readInputFile(file, kMaxMapYamlBytes, "ROS map YAML"));
  const std::string image = besideWorld(file, yaml["image"].as<std::string>());
  addGrid(out, file_field, std::move(grid), def, hashFiles({file, image}, kMaxMapFileBytes));
  out.warnings.insert(out.warnings.end(), warnings.begin(), warnings.end());
}

void readMovingAiEntry(MapSection& out, const YamlField& entry, const std::string& world) {
  const YamlMap m =
      entry.map({"movingai", "cell", "origin", "name", "kind", "height", "inflation"});
  const YamlField file_field = m.required("movingai");
  const std::string file = besideWorld(world, file_field.text());
  const EntryCommon common = readCommon(m, file);
  const YamlField cell_field = m.required("cell");
  const double cell = cell_field.inRange(1e-4, 100.0, " m");
  const Eigen::Vector2d origin = readOrigin(m.optional("origin"));
  const GridMapDef def{common.name, file, common.kind, common.height_m, true, readInflation(m)};
  std::vector<std::string> warnings;
  auto grid = located(file_field, [&] {
    return readMovingAiMap(file, cell, Pose2{origin.x(), origin.y(), 0.0}, &warnings);
  });
  addGrid(out, file_field, std::move(grid), def, hashFiles({file}, kMaxMapFileBytes));
  out.warnings.insert(out.warnings.end(), warnings.begin(), warnings.end());
}

void readSvgEntry(MapSection& out, const YamlField& entry, const std::string& world) {
  const YamlMap m =
      entry.map({"svg", "scale", "origin", "tolerance", "ids", "layers", "name", "kind", "height"});
  const YamlField file_field = m.required("svg");
  SvgMapDef def;
  def.path = besideWorld(world, file_field.text());
  const EntryCommon common = readCommon(m, def.path);
  def.prefix = common.name;
  def.kind = common.kind;
  def.height_m = common.height_m;
  if (const auto f = m.optional("scale")) {
    def.scale = f->positive();
    if (*def.scale > 1e3)
      f->fail("must be at most 1000 m per user unit, got " + f->node().Scalar());
  }
  def.origin = readOrigin(m.optional("origin"));
  if (const auto f = m.optional("tolerance")) def.tolerance_m = f->inRange(1e-6, 1.0, " m");
  std::vector<YamlField> id_fields;
  std::vector<YamlField> layer_fields;
  if (const auto f = m.optional("ids")) id_fields = f->listUpTo(10000);
  if (const auto f = m.optional("layers")) layer_fields = f->listUpTo(10000);
  for (const YamlField& f : id_fields) def.ids.push_back(f.text());
  for (const YamlField& f : layer_fields) def.layers.push_back(f.text());
  SvgMapResult r = located(file_field, [&] { return readSvgMap(def); });
  for (std::size_t k = 0; k < id_fields.size(); ++k) {
    if (!r.ids_found[k]) id_fields[k].fail("no element with this id in " + def.path);
  }
  for (std::size_t k = 0; k < layer_fields.size(); ++k) {
    if (!r.layers_found[k]) {
      layer_fields[k].fail("no layer (Inkscape label) or group id by this name in " + def.path);
    }
  }
  MapLayer layer;
  layer.name = def.prefix;
  layer.source = def.path;
  layer.content_hash = hex16(hashFiles({def.path}, kMaxSvgFileBytes));
  out.layers.push_back(std::move(layer));
  for (Obstacle& o : r.obstacles) out.obstacles.push_back(std::move(o));
  out.extent.extend(r.page);
}

}  // namespace

MapSection readMapSection(const YamlField& list, const std::string& world_source) {
  MapSection out;
  out.extent.setEmpty();
  std::size_t parts = 0;
  for (const YamlField& entry : list.listUpTo(kMaxMapEntries)) {
    const YamlMap m(entry);
    const int kinds = int(m.optional("ros").has_value()) + int(m.optional("svg").has_value()) +
                      int(m.optional("movingai").has_value());
    if (kinds != 1) {
      entry.fail(
          "a map entry names its kind once: ros: <map.yaml>, svg: <drawing.svg> or "
          "movingai: <grid.map>");
    }
    const std::size_t before = out.obstacles.size();
    if (m.optional("ros")) readRosEntry(out, entry, world_source);
    if (m.optional("svg")) readSvgEntry(out, entry, world_source);
    if (m.optional("movingai")) readMovingAiEntry(out, entry, world_source);
    for (std::size_t k = before; k < out.obstacles.size(); ++k) {
      const Obstacle& o = out.obstacles[k];
      parts += o.shape == ObstacleShape::kCompound ? o.compound->parts.size() : 1;
    }
    if (parts > kMaxMapParts) {
      entry.fail("the maps make " + std::to_string(parts) +
                 " convex parts, more than the limit of " + std::to_string(kMaxMapParts) +
                 " (docs/limits.md)");
    }
  }
  return out;
}

}  // namespace parksim
