// ROS map server maps as nav2's map_io reads them: the YAML's fields, PGM and PNG images, the
// three modes, negation, thresholds, the origin with its yaw, and the maps it refuses.

#include "parksim/scenario/maps/RosMap.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/support/MapFiles.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace ros_map_test {

namespace fs = std::filesystem;
using testing::freshDir;
using testing::writePgm;
using testing::writePng;
using testing::writeText;

constexpr int kO = static_cast<int>(MapCell::kOccupied);
constexpr int kF = static_cast<int>(MapCell::kFree);
constexpr int kU = static_cast<int>(MapCell::kUnknown);

// The grid's cells as rows from the top, like the image.
std::vector<std::vector<int>> rowsOf(const OccupancyGrid& g) {
  std::vector<std::vector<int>> rows;
  for (int j = g.height - 1; j >= 0; --j) {
    std::vector<int> row;
    for (int i = 0; i < g.width; ++i) row.push_back(static_cast<int>(g.at(i, j)));
    rows.push_back(row);
  }
  return rows;
}

std::string errorOf(const std::string& yaml_path) {
  try {
    (void)readRosMap(yaml_path);
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(RosMap, ReadsABinaryPgmTheWayMapServerDoes) {
  const fs::path dir = freshDir("ros_map_pgm");
  // map_saver's shades: 0 occupied, 254 free, 205 unknown; row 0 is the top of the map.
  writePgm(dir / "m.pgm", {{0, 254, 205}, {254, 254, 0}});
  writeText(dir / "m.yaml",
            "image: m.pgm\nresolution: 0.5\norigin: [1.0, 2.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const auto g = readRosMap((dir / "m.yaml").string());
  EXPECT_EQ(g->width, 3);
  EXPECT_EQ(g->height, 2);
  EXPECT_EQ(rowsOf(*g), (std::vector<std::vector<int>>{{kO, kF, kU}, {kF, kF, kO}}));
  // Cell (0, 0) is the image's bottom-left pixel; its outer corner is the origin.
  EXPECT_EQ(g->at(2, 0), MapCell::kOccupied);
  EXPECT_EQ(g->toLot(0, 0), Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(g->toLot(3, 2), Eigen::Vector2d(2.5, 3.0));
}

TEST(RosMap, PlainPgmSixteenBitPgmAndPngReadAlike) {
  const fs::path dir = freshDir("ros_map_formats");
  const std::string yaml = "resolution: 0.1\norigin: [0, 0, 0]\n";
  writePgm(dir / "plain.pgm", {{0, 254, 205}}, true);
  writePgm(dir / "wide.pgm", {{0, 65278, 52685}}, false, 65535);
  writePng(dir / "grey.png", 3, 1, 1, {0, 254, 205});
  writePng(dir / "rgb.png", 3, 1, 3, {0, 0, 0, 254, 254, 254, 205, 205, 205});
  for (const char* image : {"plain.pgm", "wide.pgm", "grey.png", "rgb.png"}) {
    writeText(dir / "m.yaml", std::string("image: ") + image + "\n" + yaml);
    EXPECT_EQ(rowsOf(*readRosMap((dir / "m.yaml").string())),
              (std::vector<std::vector<int>>{{kO, kF, kU}}))
        << image;
  }
}

TEST(RosMap, NegateThresholdsAndModes) {
  const fs::path dir = freshDir("ros_map_modes");
  // Shades 0, 64, 128, 192, 255: occupancy 1 - shade/255 = 1, .75, .5, .25, 0.
  writePgm(dir / "m.pgm", {{0, 64, 128, 192, 255}});
  const auto read = [&](const std::string& extra, int lethal = 100) {
    writeText(dir / "m.yaml", "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\n" + extra);
    return rowsOf(*readRosMap((dir / "m.yaml").string(), lethal)).front();
  };
  EXPECT_EQ(read("occupied_thresh: 0.65\nfree_thresh: 0.3\n"),
            (std::vector<int>{kO, kO, kU, kF, kF}));
  // Negated: white is occupied.
  EXPECT_EQ(read("negate: 1\noccupied_thresh: 0.65\nfree_thresh: 0.3\n"),
            (std::vector<int>{kF, kF, kU, kO, kO}));
  EXPECT_EQ(read("negate: true\noccupied_thresh: 0.65\nfree_thresh: 0.3\n"),
            (std::vector<int>{kF, kF, kU, kO, kO}));
  // Scale: between the thresholds a cost rint((occ - free) / (occ_t - free) * 100): 0.5 -> 57;
  // lethal at 100 by default, at 50 it is occupied.
  EXPECT_EQ(read("mode: scale\noccupied_thresh: 0.65\nfree_thresh: 0.3\n"),
            (std::vector<int>{kO, kO, kF, kF, kF}));
  EXPECT_EQ(read("mode: scale\noccupied_thresh: 0.65\nfree_thresh: 0.3\n", 57),
            (std::vector<int>{kO, kO, kO, kF, kF}));
  EXPECT_EQ(read("mode: scale\noccupied_thresh: 0.65\nfree_thresh: 0.3\n", 58),
            (std::vector<int>{kO, kO, kF, kF, kF}));
  // Raw: the value is round(255 shade); 0..100 are costs, above 100 unknown.
  EXPECT_EQ(read("mode: raw\n", 64), (std::vector<int>{kF, kO, kU, kU, kU}));
  EXPECT_EQ(read("mode: raw\n", 65), (std::vector<int>{kF, kF, kU, kU, kU}));
}

TEST(RosMap, AlphaIsAveragedInTrinaryAndUnknownInScale) {
  const fs::path dir = freshDir("ros_map_alpha");
  // Grey + alpha: white opaque, white transparent, black opaque.
  writePng(dir / "m.png", 3, 1, 2, {255, 255, 255, 0, 0, 255});
  writeText(dir / "m.yaml", "image: m.png\nresolution: 1\norigin: [0, 0, 0]\n");
  // Trinary: (3 * 1 + 0) / 4 = 0.75 shade, occupancy 0.25: between the default thresholds.
  EXPECT_EQ(rowsOf(*readRosMap((dir / "m.yaml").string())).front(), (std::vector<int>{kF, kU, kO}));
  writeText(dir / "m.yaml", "image: m.png\nresolution: 1\norigin: [0, 0, 0]\nmode: scale\n");
  EXPECT_EQ(rowsOf(*readRosMap((dir / "m.yaml").string())).front(), (std::vector<int>{kF, kU, kO}));
}

TEST(RosMap, TheOriginsYawTurnsTheMapAboutItsCorner) {
  const fs::path dir = freshDir("ros_map_yaw");
  writePgm(dir / "m.pgm", {{254, 254}});
  writeText(dir / "m.yaml", "image: m.pgm\nresolution: 0.5\norigin: [1, 1, 1.5707963267948966]\n");
  const auto g = readRosMap((dir / "m.yaml").string());
  const Eigen::Vector2d far = g->toLot(2, 1);  // 1 m along the map's x, 0.5 m along its y
  EXPECT_NEAR(far.x(), 0.5, 1e-12);
  EXPECT_NEAR(far.y(), 2.0, 1e-12);
}

// Regression (issue 39): keys map_server does not read were refused; it ignores them, and so
// does parksim, with a warning line naming the file, line and key.
TEST(RosMap, KeysMapServerIgnoresAreWarnedAboutAndIgnored) {
  const fs::path dir = freshDir("ros_map_extra_keys");
  const std::string d = dir.string() + "/";
  writePgm(dir / "m.pgm", {{0, 254}});
  writeText(dir / "m.yaml",
            "image: m.pgm\nresolution: 0.5\ncenterline: [[0, 0], [1, 0]]\norigin: [0, 0, 0]\n"
            "free_thresh: 0.196\nsaved_by: slam_toolbox\n");
  std::vector<std::string> warnings;
  const auto g = readRosMap(d + "m.yaml", 100, &warnings);
  EXPECT_EQ(rowsOf(*g), (std::vector<std::vector<int>>{{kO, kF}}));
  const std::string known =
      " (image, resolution, origin, negate, occupied_thresh, free_thresh, mode); ignored as it "
      "ignores it";
  EXPECT_EQ(warnings, (std::vector<std::string>{
                          d + "m.yaml:3: centerline: not a key nav2's map_server reads" + known,
                          d + "m.yaml:6: saved_by: not a key nav2's map_server reads" + known}));
  // A known key's bad value is still refused.
  writeText(dir / "bad.yaml",
            "image: m.pgm\nresolution: 0.5\ncenterline: 1\norigin: [0, 0, 0]\nnegate: 2\n");
  EXPECT_EQ(errorOf(d + "bad.yaml").rfind(d + "bad.yaml:5: negate: ", 0), 0u)
      << errorOf(d + "bad.yaml");
}

// Regression (issue 39): an image beyond the limits was read whole before its header refused
// it. Sparse files of 1 GiB, four times the file limit, whose headers declare too many pixels:
// refused by the pixel limit, so the header was read, and nothing after it.
TEST(RosMap, AnImageBeyondTheLimitsIsRefusedFromItsHeaderAlone) {
  const fs::path dir = freshDir("ros_map_huge");
  const std::string d = dir.string() + "/";
  const std::string yaml = "resolution: 0.05\norigin: [0, 0, 0]\n";
  writeText(dir / "huge.pgm", "P5\n# a comment\n30000 30000\n255\n");
  writePng(dir / "huge.png", 1, 1, 1, {0});
  {
    // The 1 x 1 PNG's IHDR says 100000 x 100000 (bytes 16..23, big-endian).
    std::fstream png(dir / "huge.png", std::ios::in | std::ios::out | std::ios::binary);
    png.seekp(16);
    const char size[8] = {0, 1, static_cast<char>(0x86), static_cast<char>(0xa0),
                          0, 1, static_cast<char>(0x86), static_cast<char>(0xa0)};
    png.write(size, 8);
  }
  for (const char* image : {"huge.pgm", "huge.png"}) {
    fs::resize_file(dir / image, std::uintmax_t{1} << 30);
    writeText(dir / (std::string(image) + ".yaml"), "image: " + std::string(image) + "\n" + yaml);
  }
  EXPECT_EQ(errorOf(d + "huge.pgm.yaml"),
            d + "huge.pgm: the image is 30000 x 30000 pixels, more than the limit of 20000 a "
                "side and 25000000 in all for a map (docs/limits.md)");
  EXPECT_EQ(errorOf(d + "huge.png.yaml"),
            d + "huge.png: the image is 100000 x 100000 pixels, more than the limit of 20000 a "
                "side and 25000000 in all for a map (docs/limits.md)");
}

TEST(RosMap, BadMapsAreRefusedInOneLineNamingTheFile) {
  const fs::path dir = freshDir("ros_map_bad");
  const std::string d = dir.string() + "/";
  const std::string yaml = "resolution: 0.05\norigin: [0, 0, 0]\n";
  writeText(dir / "missing.yaml", "image: nothere.pgm\n" + yaml);
  EXPECT_EQ(errorOf(d + "missing.yaml"),
            d + "nothere.pgm: cannot open map image: No such file or directory");
  writeText(dir / "truncated.pgm", "P5\n4 4\n255\n0123456789");
  writeText(dir / "truncated.yaml", "image: truncated.pgm\n" + yaml);
  EXPECT_EQ(errorOf(d + "truncated.yaml"),
            d + "truncated.pgm: truncated: the header says 4 x 4 pixels (16 bytes), the file holds "
                "10 bytes after the header");
  writeText(dir / "long.pgm", "P5\n2 2\n255\n0123456");
  writeText(dir / "long.yaml", "image: long.pgm\n" + yaml);
  EXPECT_EQ(errorOf(d + "long.yaml"),
            d + "long.pgm: size mismatch: the header says 2 x 2 pixels (4 bytes), the file holds "
                "7 bytes after the header");
  writeText(dir / "huge.pgm", "P5\n100000 100000\n255\n");
  writeText(dir / "huge.yaml", "image: huge.pgm\n" + yaml);
  EXPECT_EQ(errorOf(d + "huge.yaml"),
            d + "huge.pgm: the image is 100000 x 100000 pixels, more than the limit of 20000 a "
                "side and 25000000 in all for a map (docs/limits.md)");
  writePng(dir / "ok.png", 2, 2, 1, {0, 0, 0, 0});
  std::ifstream in(dir / "ok.png", std::ios::binary);
  std::string png((std::istreambuf_iterator<char>(in)), {});
  writeText(dir / "cut.png", png.substr(0, png.size() - 20));
  writeText(dir / "cut.yaml", "image: cut.png\n" + yaml);
  EXPECT_EQ(errorOf(d + "cut.yaml").rfind(d + "cut.png: cannot decode the PNG: ", 0), 0u)
      << errorOf(d + "cut.yaml");
  writeText(dir / "photo.jpg", "\xff\xd8\xff\xe0 not a map");
  writeText(dir / "jpg.yaml", "image: photo.jpg\n" + yaml);
  EXPECT_EQ(errorOf(d + "jpg.yaml"),
            d + "photo.jpg: not a PGM (P2 or P5) or PNG image; a map server image must be one of "
                "those (convert it, e.g. with ImageMagick: convert map.jpg map.png)");
  writePgm(dir / "m.pgm", {{0}});
  writeText(dir / "nan.yaml", "image: m.pgm\nresolution: .nan\norigin: [0, 0, 0]\n");
  EXPECT_EQ(errorOf(d + "nan.yaml"),
            d + "nan.yaml:2: resolution: must be a finite number, got .nan");
  writeText(dir / "order.yaml",
            "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nfree_thresh: 0.7\n");
  EXPECT_EQ(errorOf(d + "order.yaml"),
            d + "order.yaml:4: free_thresh: free_thresh (0.7) must not exceed occupied_thresh "
                "(0.65)");
  writeText(dir / "mode.yaml", "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: binary\n");
  EXPECT_EQ(errorOf(d + "mode.yaml"),
            d + "mode.yaml:4: mode: unknown mode \"binary\"; expected one of: trinary, scale, raw");
  writeText(dir / "plain.pgm", "P2\n2 1\n255\n0 300\n");
  writeText(dir / "plain.yaml", "image: plain.pgm\n" + yaml);
  EXPECT_EQ(errorOf(d + "plain.yaml"),
            d + "plain.pgm:4: pixel value 300 is above the maximum value 255");
}

}  // namespace ros_map_test
}  // namespace parksim
