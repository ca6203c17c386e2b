// A comparison's page links a group's paired episodes only where both sweeps kept their
// pages, the comparison's order kept, at most max_links_per_group of them.

#include "parksim/pages/ComparisonPage.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/pages/PageTestSupport.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

class ComparisonPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = parksim::testing::testOutputDir(
        std::string("ComparisonPageTest/") +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    // Both kept e1 and e3, only the baseline e2, the candidate e4.
    for (const auto& [side, ids] :
         {std::pair<std::string, std::vector<std::string>>{"base", {"e1", "e2", "e3"}},
          {"cand", {"e1", "e3", "e4"}}}) {
      for (const std::string& id : ids) {
        fs::create_directories(dir_ / side / "episodes" / id);
        std::ofstream(dir_ / side / "episodes" / id / "report.html")
            << "<!DOCTYPE html>\n</html>\n";
      }
    }
    fs::create_directories(dir_ / "ci");
  }

  nlohmann::json comparison() const {
    nlohmann::json episodes = nlohmann::json::array();
    for (const char* id : {"e3", "e2", "e4", "e1"}) {  // the comparison's order: worst first
      episodes.push_back(
          {{"id", id}, {"baseline", {{"status", "met"}}}, {"candidate", {{"status", "contact"}}}});
    }
    return {{"baseline", {{"path", "base"}, {"rows", 4}}},
            {"candidate", {{"path", "cand"}, {"rows", 4}}},
            {"groups", {{{"name", "lot / rrt / world"}, {"episodes", episodes}}}}};
  }

  fs::path dir_;
};

TEST_F(ComparisonPageTest, OnlyEpisodesBothSweepsKeptAreLinked) {
  ComparisonPage page;
  page.comparison = comparison();
  page.baseline_dir = (dir_ / "base").string();
  page.candidate_dir = (dir_ / "cand").string();
  const nlohmann::json data = comparisonPageData(page, (dir_ / "ci").string());
  const nlohmann::json& group = data["groups"][0];
  EXPECT_EQ(group["paired_episodes"], 4);
  EXPECT_EQ(group["linked_episodes"], 2);
  ASSERT_EQ(group["episodes"].size(), 2u);
  EXPECT_EQ(group["episodes"][0]["id"], "e3");
  EXPECT_EQ(group["episodes"][0]["baseline_href"], "../base/episodes/e3/report.html");
  EXPECT_EQ(group["episodes"][0]["candidate_href"], "../cand/episodes/e3/report.html");
  EXPECT_EQ(group["episodes"][1]["id"], "e1");
  EXPECT_EQ(data["page"], "comparison");
}

// Compared across the planner or the controller (compare --across), the candidate's episode
// has an id of its own: its page is linked under that id, and kept pages are needed under both.
TEST_F(ComparisonPageTest, TheCandidateIsLinkedByItsOwnIdAcrossColumns) {
  ComparisonPage page;
  page.comparison = comparison();
  nlohmann::json& episodes = page.comparison["groups"][0]["episodes"];
  episodes[0]["candidate_id"] = "e4";  // baseline e3 paired with candidate e4
  episodes[2]["candidate_id"] = "e2";  // baseline e4 (not kept) with candidate e2 (not kept)
  page.baseline_dir = (dir_ / "base").string();
  page.candidate_dir = (dir_ / "cand").string();
  const nlohmann::json data = comparisonPageData(page, (dir_ / "ci").string());
  const nlohmann::json& group = data["groups"][0];
  ASSERT_EQ(group["linked_episodes"], 2);
  EXPECT_EQ(group["episodes"][0]["baseline_href"], "../base/episodes/e3/report.html");
  EXPECT_EQ(group["episodes"][0]["candidate_href"], "../cand/episodes/e4/report.html");
  EXPECT_EQ(group["episodes"][1]["id"], "e1");
}

TEST_F(ComparisonPageTest, LinksAreCappedAndNeedBothSweeps) {
  ComparisonPage page;
  page.comparison = comparison();
  page.baseline_dir = (dir_ / "base").string();
  page.candidate_dir = (dir_ / "cand").string();
  page.max_links_per_group = 1;
  EXPECT_EQ(comparisonPageData(page, ".")["groups"][0]["linked_episodes"], 1);
  page.candidate_dir.clear();  // a results.jsonl outside a sweep directory: nothing to link
  page.max_links_per_group = 50;
  EXPECT_EQ(comparisonPageData(page, ".")["groups"][0]["linked_episodes"], 0);
}

TEST_F(ComparisonPageTest, ThePageIsWrittenWhole) {
  ComparisonPage page;
  page.comparison = comparison();
  page.baseline_dir = (dir_ / "base").string();
  page.candidate_dir = (dir_ / "cand").string();
  writeComparisonPage((dir_ / "ci" / "compare.html").string(), page);
  std::ifstream in(dir_ / "ci" / "compare.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const nlohmann::json data = testing::pageData(html);
  EXPECT_EQ(data["groups"][0]["episodes"][1]["candidate_href"], "../cand/episodes/e1/report.html");
  EXPECT_NE(html.find("<title>parksim compare: base vs cand</title>"), std::string::npos);
}

}  // namespace
}  // namespace parksim
