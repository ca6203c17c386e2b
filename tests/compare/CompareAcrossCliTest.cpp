// `parksim compare --across` end to end (issue 30: a user's planner and controller compared
// with parksim's): real sweeps of one small spec (parallel and head_in under `lab`, noise seeds
// 1..6) with time-a-star and parksim's tracking controller, with the example plugin's planner
// (`example`) and with its controller (`pure-pursuit`). Without --across the planners share no
// group and the controllers no episode id; across them every episode pairs with its own, and
// the numbers the report prints are those of the paired rows.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using ::testing::HasSubstr;
using ::testing::Not;
using Json = nlohmann::json;

class CompareAcrossCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::testOutputDir("compare_across_cli") /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  // Sweeps the small spec with `extra` lines (planners:, controllers:, plugins:) into out/NAME.
  std::string sweep(const std::string& name, const std::string& extra) const {
    const std::string worlds = testing::sourceDir() + "/worlds/";
    const fs::path spec = dir_ / (name + ".yaml");
    std::ofstream(spec) << "format: parksim-sweep/1\nname: across\n"
                        << "worlds: [" << worlds << "parallel.yaml, " << worlds << "head_in.yaml]\n"
                        << "realism: lab\nnoise_seeds: {from: 1, to: 6}\n"
                        << extra;
    const std::string out = (dir_ / name).string();
    const CliRun r =
        testing::runParksim("sweep " + spec.string() + " --out " + out + " --workers 2");
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.out;  // 1: an episode missed
    return out;
  }

  static std::string plugin() {
    return testing::binaryDir() + "/examples/plugins/libparksim_example_plugins.so";
  }

  fs::path dir_;
};

std::vector<Json> rowsOf(const std::string& dir) {
  std::vector<Json> rows;
  std::ifstream in(dir + "/results.jsonl");
  for (std::string line; std::getline(in, line);) rows.push_back(Json::parse(line));
  return rows;
}

// The median (R's type 7, as compare's) of a column over the rows of one world, in mm as the
// summary prints it.
std::string medianMm(const std::vector<Json>& rows, const std::string& world, const char* column) {
  std::vector<double> v;
  for (const Json& row : rows) {
    if (row["world"] == world && row[column].is_number()) v.push_back(row[column].get<double>());
  }
  std::sort(v.begin(), v.end());
  const double h = 0.5 * (static_cast<double>(v.size()) - 1.0);
  const auto lo = static_cast<std::size_t>(h);
  const double m =
      v[lo] + (h - static_cast<double>(lo)) * (v[std::min(lo + 1, v.size() - 1)] - v[lo]);
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(3);
  s << 1e3 * m << " mm";
  return s.str();
}

// What the paired rows of one world say about the max tracking error: every episode's grew
// beyond compare's default margin (10 % and 0.01 mm), or none did.
struct Change {
  bool all_beyond = true;
  bool none_beyond = true;
};

Change pairedChange(const std::vector<Json>& b, const std::vector<Json>& c,
                    const std::string& world) {
  std::map<std::uint64_t, double> before;
  for (const Json& row : b) {
    if (row["world"] == world) before[row["noise_seed"]] = row["max_pos_err_m"];
  }
  Change change;
  for (const Json& row : c) {
    if (row["world"] != world) continue;
    const double x = before.at(row["noise_seed"]);
    const double y = row["max_pos_err_m"];
    change.all_beyond = change.all_beyond && y > std::max(1.1 * x, x + 1e-5);
    change.none_beyond = change.none_beyond && y <= std::max(1.1 * x, x + 1e-5);
  }
  return change;
}

// The summary's line of a metric whose two sides read `sides`.
std::string lineWith(const std::string& text, const std::string& sides) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.find(sides) != std::string::npos) return line;
  }
  return "";
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The user's planner against time-a-star: refused without --across as tables of other specs;
// across the planner each world's 6 episodes pair, and the medians printed are the rows'.
TEST_F(CompareAcrossCli, APlannerPairsEveryEpisodeAcrossThePlanner) {
  const std::string base = sweep("time-a-star", "planners: [time-a-star]\n");
  const std::string mine = sweep("example", "plugins: [" + plugin() + "]\nplanners: [example]\n");
  CliRun r = testing::runParksim("compare " + base + " " + mine);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_THAT(r.out, HasSubstr("no world / planner / realism group is in both tables"));

  const std::string junit = (dir_ / "r.xml").string();
  const std::string html = (dir_ / "r.html").string();
  r = testing::runParksim("compare " + base + " " + mine + " --across planner --junit " + junit +
                          " --html " + html);
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 4) << r.out;
  EXPECT_THAT(r.out, HasSubstr("Compared across `planner`"));
  // The planner's place in the label reads "*" (time-a-star's label: "time-a-star+smooth").
  EXPECT_EQ(count(r.out, " / *+smooth / lab (planner: time-a-star vs example) | 6 paired |"), 2u)
      << r.out;
  const std::vector<Json> b = rowsOf(base);
  const std::vector<Json> c = rowsOf(mine);
  bool any_beyond = false;
  for (const char* world : {"parallel", "head_in"}) {
    // A paired row of the summary: the medians of the group's rows on each side ...
    const std::string line =
        lineWith(r.out, "| max tracking error median | " + medianMm(b, world, "max_pos_err_m") +
                            " | " + medianMm(c, world, "max_pos_err_m") + " |");
    ASSERT_FALSE(line.empty()) << world << "\n" << r.out;
    // ... and its verdict the data's: every paired episode beyond the margin is a regression
    // (6 of 6 pairs: p = 1 / 10001 before Holm), none beyond is none.
    const Change change = pairedChange(b, c, world);
    EXPECT_TRUE(change.all_beyond || change.none_beyond) << world << ": mixed data, pick another";
    EXPECT_EQ(line.find("**regression**") != std::string::npos, change.all_beyond) << line;
    any_beyond = any_beyond || change.all_beyond;
  }
  EXPECT_EQ(r.exit_code, any_beyond ? 4 : 0);
  const std::string xml = testing::slurp(junit);
  EXPECT_THAT(xml, HasSubstr("name=\"baseline.planner\" value=\"time-a-star\""));
  EXPECT_THAT(xml, HasSubstr("name=\"candidate.planner\" value=\"example\""));
  EXPECT_THAT(testing::slurp(html), HasSubstr("\"across\":[\"planner\"]"));
}

// The user's controller against parksim's tracking: the groups match, the ids do not (they
// spell ";controller=pure-pursuit"), so only --across controller pairs the episodes.
TEST_F(CompareAcrossCli, AControllerPairsTrackingWithPurePursuitAcrossTheController) {
  const std::string base = sweep("tracking", "");
  const std::string mine =
      sweep("pure-pursuit", "plugins: [" + plugin() + "]\ncontrollers: [pure-pursuit]\n");
  // Two controllers are two groups, as two planners are: refused, pointing to --across.
  CliRun r = testing::runParksim("compare " + base + " " + mine);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_THAT(r.out, HasSubstr("compare with --across"));
  r = testing::runParksim("compare " + base + " " + mine + " --across controller");
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 4) << r.out;
  EXPECT_EQ(count(r.out, " / lab (controller: tracking vs pure-pursuit) | 6 paired |"), 2u)
      << r.out;
  EXPECT_THAT(r.out, Not(HasSubstr("unpaired")));
}

// A column that cannot be compared across is one line naming the option and what it takes,
// exit 2, nothing written.
TEST_F(CompareAcrossCli, ABadColumnIsOneLineAndExit2) {
  const std::string md = (dir_ / "r.md").string();
  const CliRun r = testing::runParksim("compare a b --across planner,seed --markdown " + md);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_THAT(r.out, HasSubstr("--across: 'seed' is not a column to compare across (allowed: "
                               "planner, controller, planner.NAME, controller.NAME)\n"));
  EXPECT_FALSE(fs::exists(md));
}

}  // namespace
}  // namespace parksim
