// An episode's page: written beside metrics.json by every pipeline call that keeps files, with
// the record exact, nothing wall-clock in it (the same episode, the same bytes), a page for
// episodes that were never driven, and text from a world file unable to break out of it.

#include "parksim/pages/EpisodePage.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/scenario/world/World.h"
#include "tests/pages/PageTestSupport.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using ::testing::Contains;
using ::testing::HasSubstr;
using testing::pageData;
using testing::unpack;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class EpisodePageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = parksim::testing::testOutputDir(
        std::string("EpisodePageTest/") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    world_ = std::make_shared<const World>(
        loadWorld(parksim::testing::sourceDir() + "/worlds/head_in.yaml"));
  }

  EpisodeOutcome run(const std::string& name, const std::string& realism = "world") {
    EpisodeRequest r;
    r.world = world_;
    r.realism = realism;
    r.record.executed_rate_hz = 60.0;
    r.out_dir = (dir_ / name).string();
    return runEpisodePipeline(r);
  }

  fs::path dir_;
  std::shared_ptr<const World> world_;
};

TEST_F(EpisodePageTest, ARunWritesItsPageWithTheRecordExact) {
  const EpisodeOutcome out = run("run");
  EXPECT_THAT(out.files, Contains("report.html"));
  const nlohmann::json data = pageData(slurp(dir_ / "run" / "report.html"));
  EXPECT_EQ(data["page"], "episode");
  EXPECT_EQ(data["verdict"]["status"], "met");
  EXPECT_EQ(data["verdict"]["met"], true);
  EXPECT_EQ(data["scenario"], "head_in");
  EXPECT_EQ(data["obstacles"].size(), world_->scenario.obstacles.size());
  EXPECT_EQ(data["record"]["rows"], out.episode.rows.size());
  // Every column of executed.csv, by name, bit for bit.
  const std::vector<DataColumn> columns = readRecordFile((dir_ / "run" / "executed.csv").string());
  ASSERT_EQ(data["record"]["names"].size(), columns.size());
  for (const DataColumn& c : columns) {
    const std::vector<double> values = unpack(data["record"]["columns"][c.name]);
    EXPECT_EQ(values, c.values) << c.name;
  }
  // The plan's poses, and the tolerance judged.
  const std::vector<double> t = unpack(data["plan"]["t"]);
  ASSERT_EQ(t.size(), out.trajectory.points.size());
  EXPECT_EQ(t.back(), out.trajectory.points.back().t_s);
  EXPECT_EQ(unpack(data["plan"]["x"]).back(), out.trajectory.points.back().pose.x);
  EXPECT_EQ(data["tolerance"]["max_pos_err_m"], out.tolerance.max_pos_err_m);
  EXPECT_EQ(data["metrics"]["max_pos_err_m"], out.episode.metrics.max_pos_err_m);
  EXPECT_FALSE(data["metrics"].contains("wall_time_s"));
  EXPECT_FALSE(data.contains("contacts") && !data["contacts"].empty());
}

TEST_F(EpisodePageTest, TheSameEpisodeGivesTheSameBytes) {
  run("a");
  run("b");
  const std::string a = slurp(dir_ / "a" / "report.html");
  EXPECT_GT(a.size(), 100000u);
  EXPECT_EQ(a, slurp(dir_ / "b" / "report.html"));
  // metrics.json, for comparison, holds wall-clock times.
  EXPECT_THAT(slurp(dir_ / "a" / "metrics.json"), HasSubstr("wall_time_s"));
}

TEST_F(EpisodePageTest, UnderARealismTheRecordCarriesTheEstimate) {
  run("lab", "lab");
  const nlohmann::json data = pageData(slurp(dir_ / "lab" / "report.html"));
  EXPECT_THAT(data["record"]["names"], Contains("x_est"));
  EXPECT_THAT(data["record"]["names"], Contains("est_pos_err"));
  EXPECT_EQ(data["metrics"]["realism"], "lab");
}

TEST_F(EpisodePageTest, AnEpisodeNeverDrivenStillHasAPage) {
  EpisodeRequest r;
  r.world = world_;
  r.plan.planner = "rrt";
  r.plan.search.max_iterations = 3;
  r.out_dir = (dir_ / "unplanned").string();
  const EpisodeOutcome out = runEpisodePipeline(r);
  ASSERT_EQ(out.verdict.status, EpisodeStatus::kPlanFailed);
  EXPECT_THAT(out.files, Contains("report.html"));
  const nlohmann::json data = pageData(slurp(dir_ / "unplanned" / "report.html"));
  EXPECT_EQ(data["verdict"]["status"], "plan_failed");
  EXPECT_EQ(data["verdict"]["reason"], out.verdict.reason);
  EXPECT_FALSE(data.contains("record"));
  EXPECT_FALSE(data.contains("plan"));
  EXPECT_FALSE(data.contains("metrics"));
}

TEST_F(EpisodePageTest, ALongRecordIsKeptEveryNthRowAndItsLast) {
  // One row more than a page holds: every second row, the last included.
  std::vector<ExecutedRow> rows(kMaxEpisodePageRows + 1);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].t_s = static_cast<double>(i);
  EpisodePage page;
  page.status = "met";
  page.rows = rows;
  nlohmann::json data = episodePageData(world_->scenario, page);
  EXPECT_EQ(data["record"]["stride"], 2);
  std::vector<double> t = unpack(data["record"]["columns"]["t"]);
  ASSERT_EQ(t.size(), kMaxEpisodePageRows / 2 + 1);
  EXPECT_EQ(t[1], 2.0);
  EXPECT_EQ(t.back(), static_cast<double>(kMaxEpisodePageRows));
  // As many as it holds: all of them.
  rows.pop_back();
  page.rows = rows;
  data = episodePageData(world_->scenario, page);
  EXPECT_EQ(data["record"]["stride"], 1);
  EXPECT_EQ(data["record"]["rows"], kMaxEpisodePageRows);
}

TEST_F(EpisodePageTest, TextFromAWorldFileCannotCloseTheDataScript) {
  Scenario scenario = world_->scenario;
  scenario.name = "lot</script><script>alert(1)</script><!--";
  scenario.obstacles.front().name = "</SCRIPT >";
  EpisodePage page;
  page.status = "contact";
  page.reason = "touched </script> at 1 s";
  const fs::path path = dir_ / "hostile.html";
  writeEpisodePage(path.string(), scenario, page);
  const std::string html = slurp(path);
  const std::string open = "id=\"parksim-data\">";
  const std::size_t begin = html.find(open);
  const std::size_t end = html.find("</script>", begin);
  const std::string json = html.substr(begin + open.size(), end - begin - open.size());
  EXPECT_EQ(json.find('<'), std::string::npos);
  const nlohmann::json data = pageData(html);
  EXPECT_EQ(data["scenario"], scenario.name);
  EXPECT_EQ(data["obstacles"][0]["name"], "</SCRIPT >");
  EXPECT_EQ(data["verdict"]["reason"], page.reason);
  // The title, too, is text.
  EXPECT_THAT(html, HasSubstr("<title>parksim episode: lot&lt;/script&gt;&lt;script&gt;"));
}

}  // namespace
}  // namespace parksim
