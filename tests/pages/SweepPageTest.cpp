// A sweep's page: its axes are the rows' parameters, each kept episode is linked by a path
// relative to the page, and a JUnit report points its readers at both.

#include "parksim/pages/SweepPage.h"

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/pages/EpisodeFolderCheck.h"
#include "parksim/pages/JUnitPageLinks.h"
#include "tests/pages/PageTestSupport.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::vector<Json> rows() {
  std::vector<Json> out;
  for (const char* id : {"aaa", "bbb", "../x", "ccc"}) {
    Json r;
    r["episode_id"] = id;
    r["world"] = "head_in";
    r["set.robot.max_wheel_speed_radps"] = 6;
    r["seed"] = 1;
    r["noise_seed"] = 1;
    r["status"] = "met";
    r["met_tolerance"] = true;
    r["max_pos_err_m"] = 1e-4;
    out.push_back(r);
  }
  return out;
}

class SweepPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = parksim::testing::testOutputDir(
        std::string("SweepPageTest/") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sweep" / "episodes" / "aaa");
    fs::create_directories(dir_ / "sweep" / "episodes" / "bbb");
    fs::create_directories(dir_ / "sweep" / "episodes" / "ccc");
    std::ofstream(dir_ / "sweep" / "episodes" / "aaa" / "report.html")
        << "<!DOCTYPE html>\n<html>...</html>\n";
    // Cut short: as a full disk or a stopped copy leaves it, it opens blank.
    std::ofstream(dir_ / "sweep" / "episodes" / "ccc" / "report.html")
        << "<!DOCTYPE html>\n<html>...";
    std::ofstream(dir_ / "x") << "not an episode";
  }
  fs::path dir_;
};

TEST_F(SweepPageTest, TheParametersAreTheKeysBeforeTheStatusButTheReplicates) {
  // A seed (as a noise seed or a sample) is a replicate of the same episode, never an axis.
  EXPECT_EQ(parameterColumns(rows()),
            (std::vector<std::string>{"world", "set.robot.max_wheel_speed_radps"}));
  EXPECT_TRUE(parameterColumns({}).empty());
}

TEST_F(SweepPageTest, OnlyEpisodesWithAPageAreLinked) {
  const std::string episodes = (dir_ / "sweep" / "episodes").string();
  // bbb's folder has no page; "../x" names a file outside the folder and is never a page;
  // ccc's page is cut short.
  EXPECT_EQ(keptEpisodePages(episodes, rows()), (std::vector<bool>{true, false, false, false}));
  EXPECT_TRUE(keptEpisodePage(episodes, "ccc").empty());
  EXPECT_FALSE(keptEpisodePage(episodes, "aaa").empty());
  EXPECT_TRUE(keptEpisodePage(episodes, "..").empty());
  EXPECT_TRUE(keptEpisodePage(episodes, "").empty());
}

TEST_F(SweepPageTest, DamagedFoldersAreNamedOneLineEach) {
  const std::string episodes = (dir_ / "sweep" / "episodes").string();
  std::ofstream(dir_ / "sweep" / "episodes" / "ccc" / "metrics.json") << "{\"a\": 1";
  std::ofstream(dir_ / "sweep" / "episodes" / "aaa" / "plan.json") << "{\"a\": 1}";
  EXPECT_EQ(episodeFolderProblems(episodes, rows()),
            (std::vector<std::string>{
                episodes + "/bbb: report.html is missing",
                episodes + "/ccc: report.html is cut short or not a page; metrics.json is not "
                           "JSON"}));
  EXPECT_EQ(episodeFolderProblem(dir_ / "x"), "not a folder");
}

TEST_F(SweepPageTest, LinksAreRelativeToThePage) {
  EXPECT_EQ(relativeHref("out/study/report", "out/study/episodes"), "../episodes");
  EXPECT_EQ(relativeHref("ci", "out/study/episodes/aaa/report.html"),
            "../out/study/episodes/aaa/report.html");
  EXPECT_EQ(relativeHref(".", "a/b"), "a/b");
}

TEST_F(SweepPageTest, ALinkIsAPathWhateverItsFoldersAreNamed) {
  EXPECT_EQ(hrefOf("../episodes"), "../episodes");
  EXPECT_EQ(hrefOf("Az09-._~/x"), "Az09-._~/x");
  // Not a scheme, a query, a fragment, an escape or a space.
  EXPECT_EQ(hrefOf("javascript:alert(1)/episodes"), "javascript%3Aalert%281%29/episodes");
  EXPECT_EQ(hrefOf("../a b/c?d#e%f/r.html"), "../a%20b/c%3Fd%23e%25f/r.html");
  EXPECT_EQ(hrefOf("\"<x>'"), "%22%3Cx%3E%27");
  EXPECT_EQ(hrefOf("caf\xC3\xA9"), "caf%C3%A9");
}

TEST_F(SweepPageTest, TheDataHoldsTheTableTheAxesAndTheKeptFlags) {
  const std::vector<Json> table = rows();
  SweepPage page;
  page.title = "study";
  page.source = "out/study";
  page.rows = &table;
  page.axes = parameterColumns(table);
  page.statuses = {"met", "contact"};
  page.episodes_href = "../episodes";
  page.kept = {true, false, false, false};
  const fs::path path = dir_ / "index.html";
  writeSweepPage(path.string(), page);
  std::ifstream in(path);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const nlohmann::json data = testing::pageData(html);
  EXPECT_EQ(data["page"], "sweep");
  EXPECT_EQ(data["table"]["rows"], 4);
  EXPECT_EQ(data["axes"], page.axes);
  EXPECT_EQ(data["statuses"], page.statuses);
  EXPECT_EQ(testing::unpack(data["episodes"]["kept"]), (std::vector<double>{1, 0, 0, 0}));
  page.kept = {true};
  EXPECT_THROW(sweepPageData(page), Error);
}

TEST_F(SweepPageTest, JUnitCasesLinkTheirEpisodesPages) {
  JUnitReport report{"study", {}};
  JUnitSuite suite{"head_in / rrt / world", {}, {}};
  JUnitCase kept;
  kept.name = "seed=1";
  kept.properties = {{"episode_id", "aaa"}, {"seed", "1"}};
  JUnitCase other;
  other.name = "seed=2";
  other.properties = {{"episode_id", "bbb"}};
  suite.cases = {kept, other};
  report.suites = {suite};
  linkJUnitToPages(report, (dir_ / "study.xml").string(),
                   (dir_ / "sweep" / "report" / "index.html").string(),
                   (dir_ / "sweep" / "episodes").string());
  const JUnitSuite& s = report.suites.front();
  ASSERT_EQ(s.properties.size(), 1u);
  EXPECT_EQ(s.properties[0].name, "html_report");
  EXPECT_EQ(s.properties[0].value, "sweep/report/index.html");
  ASSERT_EQ(s.cases[0].properties.size(), 3u);
  EXPECT_EQ(s.cases[0].properties[2].name, "episode_report");
  EXPECT_EQ(s.cases[0].properties[2].value, "sweep/episodes/aaa/report.html");
  EXPECT_EQ(s.cases[1].properties.size(), 1u);  // no page: no link
}

}  // namespace
}  // namespace parksim
