#include "parksim/scenario/maps/RosMap.h"

#include <cmath>
#include <filesystem>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/Text.h"
#include "parksim/scenario/maps/MapImage.h"
#include "parksim/scenario/maps/MapLimits.h"
#include "parksim/scenario/yaml/YamlField.h"

namespace parksim {

namespace {

enum class RosMapMode { kTrinary, kScale, kRaw };

// The keys nav2's map_server (map_io's loadMapYaml) reads.
constexpr const char* kRosMapKeys[] = {"image",           "resolution",  "origin", "negate",
                                       "occupied_thresh", "free_thresh", "mode"};

// nav2 accepts negate as 0/1 or as a boolean.
bool readNegate(const YamlField& f) {
  const std::string& s = f.node().IsScalar() ? f.node().Scalar() : std::string();
  if (s == "0") return false;
  if (s == "1") return true;
  return f.boolean();
}

}  // namespace

std::shared_ptr<const OccupancyGrid> readRosMap(const std::string& yaml_path, int lethal_threshold,
                                                std::vector<std::string>* warnings) {
  const std::string text = readInputFile(yaml_path, kMaxMapYamlBytes, "ROS map YAML");
  const YAML::Node document = loadSingleYamlDocument(text, yaml_path, "ROS map YAML",
                                                     "image: <file>, resolution: <m>, ...");
  const YamlField root(document, "", 1, yaml_path);
  const YamlMap m(root);
  // Keys nav2's map_server does not read (a `centerline`, a tool's notes) it ignores; so does
  // parksim, with a warning, since a misspelt key is ignored the same way.
  for (const std::string& key : m.keys()) {
    bool known = false;
    for (const char* k : kRosMapKeys) known = known || key == k;
    if (known || !warnings) continue;
    std::string names;
    for (const char* k : kRosMapKeys) names += std::string(names.empty() ? "" : ", ") + k;
    warnings->push_back(escapeText(yaml_path + ":" + std::to_string(m.optional(key)->line()) +
                                   ": " + key + ": not a key nav2's map_server reads (" + names +
                                   "); ignored as it ignores it"));
  }
  const YamlField image_field = m.required("image");
  const std::string image = image_field.text();
  const YamlField res_field = m.required("resolution");
  const double resolution = res_field.number();
  if (!(resolution >= 1e-4 && resolution <= 100.0)) {
    res_field.fail("must be in [0.0001, 100] m per pixel, got " + res_field.node().Scalar());
  }
  const std::vector<double> origin = m.required("origin").numbers(3, "[x, y, yaw]");
  const std::vector<YamlField> origin_items = m.required("origin").items();
  for (int k = 0; k < 2; ++k) origin_items[static_cast<std::size_t>(k)].inRange(-1e4, 1e4, " m");
  origin_items[2].inRange(-100.0, 100.0, " rad");
  const bool negate = m.optional("negate") ? readNegate(*m.optional("negate")) : false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  if (const auto f = m.optional("occupied_thresh")) occupied_thresh = f->inRange(0.0, 1.0);
  if (const auto f = m.optional("free_thresh")) free_thresh = f->inRange(0.0, 1.0);
  if (!(free_thresh <= occupied_thresh)) {
    (m.optional("free_thresh") ? *m.optional("free_thresh") : *m.optional("occupied_thresh"))
        .fail("free_thresh (" + formatNumber(free_thresh) + ") must not exceed occupied_thresh (" +
              formatNumber(occupied_thresh) + ")");
  }
  RosMapMode mode = RosMapMode::kTrinary;
  if (const auto f = m.optional("mode")) {
    const std::string s = f->text();
    if (s == "trinary") {
      mode = RosMapMode::kTrinary;
    } else if (s == "scale") {
      mode = RosMapMode::kScale;
      if (!(free_thresh < occupied_thresh)) {
        f->fail("scale mode needs free_thresh below occupied_thresh");
      }
    } else if (s == "raw") {
      mode = RosMapMode::kRaw;
    } else {
      f->fail("unknown mode \"" + s + "\"; expected one of: trinary, scale, raw");
    }
  }

  // The image, relative to the YAML's folder (map_server's rule).
  std::filesystem::path image_path(image);
  if (image_path.is_relative()) {
    image_path = std::filesystem::path(yaml_path).parent_path() / image_path;
  }
  const MapImage img = readMapImage(image_path.lexically_normal().string());

  auto grid = std::make_shared<OccupancyGrid>();
  grid->width = img.width;
  grid->height = img.height;
  grid->resolution_m = resolution;
  grid->origin = {origin[0], origin[1], origin[2]};
  grid->cells.resize(img.shade.size());
  for (int r = 0; r < img.height; ++r) {
    for (int i = 0; i < img.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(r) * static_cast<std::size_t>(img.width) +
                            static_cast<std::size_t>(i);
      double shade = img.shade[k];
      const double opacity = img.has_alpha ? double(img.opacity[k]) : 1.0;
      if (mode == RosMapMode::kTrinary && img.has_alpha) shade = (3.0 * shade + opacity) / 4.0;
      const double occ = negate ? shade : 1.0 - shade;
      int value = -1;  // unknown
      switch (mode) {
        case RosMapMode::kTrinary:
          value = occupied_thresh < occ ? 100 : occ < free_thresh ? 0 : -1;
          break;
        case RosMapMode::kScale:
          if (opacity < 1.0) {
            value = -1;
          } else if (occupied_thresh < occ) {
            value = 100;
          } else if (occ < free_thresh) {
            value = 0;
          } else {
            value = static_cast<int>(
                std::rint((occ - free_thresh) / (occupied_thresh - free_thresh) * 100.0));
          }
          break;
        case RosMapMode::kRaw: {
          const double v = std::round(shade * 255.0);
          value = v >= 0.0 && v <= 100.0 ? static_cast<int>(v) : -1;
          break;
        }
      }
      const MapCell cell = value < 0                   ? MapCell::kUnknown
                           : value >= lethal_threshold ? MapCell::kOccupied
                                                       : MapCell::kFree;
      // The image's top row is the map's last (map_server flips it).
      const std::size_t j = static_cast<std::size_t>(img.height - 1 - r);
      grid->cells[j * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(i)] =
          static_cast<std::uint8_t>(cell);
    }
  }
  return grid;
}

}  // namespace parksim
