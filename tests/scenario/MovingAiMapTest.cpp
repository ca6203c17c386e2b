// Moving AI benchmark grids: header, terrain letters, rows from the top, and what is refused.

#include "parksim/scenario/maps/MovingAiMap.h"

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/support/MapFiles.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace moving_ai_map_test {

std::string errorOf(const std::filesystem::path& path) {
  try {
    (void)readMovingAiMap(path.string(), 0.1, {});
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(MovingAiMap, ReadsTerrainRowsFromTheTop) {
  const auto dir = testing::freshDir("movingai_read");
  testing::writeText(dir / "m.map",
                     "type octile\r\nheight 2\r\nwidth 4\r\nmap\r\n.GST\r\n@OW.\r\n");
  const auto g = readMovingAiMap((dir / "m.map").string(), 0.25, {1.0, 2.0, 0.0});
  ASSERT_EQ(g->width, 4);
  ASSERT_EQ(g->height, 2);
  const MapCell f = MapCell::kFree;
  const MapCell o = MapCell::kOccupied;
  // Bottom row (the file's last): @ O W .
  EXPECT_EQ((std::vector<MapCell>{g->at(0, 0), g->at(1, 0), g->at(2, 0), g->at(3, 0)}),
            (std::vector<MapCell>{o, o, o, f}));
  EXPECT_EQ((std::vector<MapCell>{g->at(0, 1), g->at(1, 1), g->at(2, 1), g->at(3, 1)}),
            (std::vector<MapCell>{f, f, f, o}));
  EXPECT_EQ(g->toLot(4, 2), Eigen::Vector2d(2.0, 2.5));
}

TEST(MovingAiMap, RefusesWhatItCannotHonourInOneLocatedLine) {
  const auto dir = testing::freshDir("movingai_bad");
  const std::string d = dir.string() + "/";
  testing::writeText(dir / "a.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  EXPECT_EQ(errorOf(dir / "a.map"),
            d + "a.map:6: size mismatch: the row has 2 cells, the header says width 3");
  testing::writeText(dir / "b.map", "type octile\nheight 3\nwidth 3\nmap\n...\n...\n");
  EXPECT_EQ(errorOf(dir / "b.map"),
            d + "b.map:6: size mismatch: the header says 3 rows, the file ends after 2");
  testing::writeText(dir / "c.map", "type octile\nheight 1\nwidth 3\nmap\n.x.\n");
  EXPECT_EQ(errorOf(dir / "c.map"),
            d + "c.map:5: column 2: 'x' is no Moving AI terrain (. G S passable, @ O T W blocked)");
  testing::writeText(dir / "d.map", "type octile\nheight 100000\nwidth 100000\nmap\n");
  EXPECT_EQ(errorOf(dir / "d.map"),
            d + "d.map:3: the map is 100000 x 100000 cells; a map has at least one and at most "
                "20000 a side and 25000000 in all (docs/limits.md)");
  testing::writeText(dir / "e.map", "type tile\n");
  EXPECT_EQ(errorOf(dir / "e.map"),
            d + "e.map:1: expected 'type octile' (a Moving AI .map file), got 'type tile'");
}

// Regression (issue 39): text after the grid was "more rows than the header's height". Moving
// AI's readers read the header's rows and ignore the rest; so does parksim, saying so.
TEST(MovingAiMap, TextAfterTheGridIsIgnoredWithAWarningNamingItsLine) {
  const auto dir = testing::freshDir("movingai_trailing");
  const std::string d = dir.string() + "/";
  testing::writeText(dir / "f.map",
                     "type octile\nheight 1\nwidth 2\nmap\n.@\n\n# drawn by hand\n.\n");
  std::vector<std::string> warnings;
  const auto g = readMovingAiMap(d + "f.map", 0.1, {}, &warnings);
  EXPECT_EQ(g->height, 1);
  EXPECT_EQ(g->at(1, 0), MapCell::kOccupied);
  EXPECT_EQ(
      warnings,
      (std::vector<std::string>{d + "f.map:7: trailing text after the header's 1 rows; ignored, as "
                                    "Moving AI's readers ignore it"}));
}

// Regression (issue 39): a grid beyond the limits was read whole before its header refused
// it. A sparse file of 1 GiB, four times the file limit, whose header declares too many cells:
// refused by the cell limit, so the header was read, and nothing after it.
TEST(MovingAiMap, AGridBeyondTheLimitsIsRefusedFromItsHeaderAlone) {
  const auto dir = testing::freshDir("movingai_huge");
  const std::string d = dir.string() + "/";
  for (const auto& [name, size] : {std::pair{"huge.map", "30000"}, {"many.map", "6000"}}) {
    testing::writeText(dir / name,
                       std::string("type octile\nheight ") + size + "\nwidth " + size + "\nmap\n");
    std::filesystem::resize_file(dir / name, std::uintmax_t{1} << 30);
    ASSERT_EQ(std::filesystem::file_size(dir / name), std::uintmax_t{1} << 30);
  }
  EXPECT_EQ(errorOf(dir / "huge.map"),
            d + "huge.map:3: the map is 30000 x 30000 cells; a map has at least one and at most "
                "20000 a side and 25000000 in all (docs/limits.md)");
  EXPECT_EQ(errorOf(dir / "many.map"),
            d + "many.map:3: the map is 6000 x 6000 cells; a map has at least one and at most "
                "20000 a side and 25000000 in all (docs/limits.md)");
}

}  // namespace moving_ai_map_test
}  // namespace parksim
