// `parksim report` over what users put in a sweep directory: worlds named with any text, and
// episode folders cut short, emptied or overwritten after the sweep.

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using testing::runParksim;
using testing::scratchDir;
using testing::slurp;
using testing::writeText;

// worlds/head_in.yaml named `name` at `path`.
void renamedWorld(const std::string& path, const std::string& name) {
  std::string text = slurp(testing::sourceDir() + "/worlds/head_in.yaml");
  const std::string line = "\nname: head_in\n";
  text.replace(text.find(line), line.size(), "\nname: \"" + name + "\"\n");
  writeText(path, text);
}

TEST(ReportCli, AWorldNamedWithSlashesNamesNoFolder) {
  const std::string dir = scratchDir();
  // Two names that a file name made by replacing '/' would join.
  renamedWorld(dir + "/a.yaml", "lots/../a");
  renamedWorld(dir + "/b.yaml", "lots_.._a");
  writeText(dir + "/spec.yaml",
            "format: parksim-sweep/1\nname: slashes\nworlds: [a.yaml, b.yaml]\nseeds: [1]\n");
  const std::string out = dir + "/out";
  ASSERT_EQ(runParksim("sweep " + dir + "/spec.yaml --out " + out + " -q").exit_code, 0);
  const auto report = runParksim("report " + out);
  ASSERT_EQ(report.exit_code, 0) << report.out;
  int logs = 0;
  for (const auto& entry : fs::directory_iterator(out + "/report")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ompl_", 0) != 0) continue;
    ++logs;
    EXPECT_TRUE(entry.is_regular_file()) << name;
    EXPECT_LE(name.size(), 80u) << name;
    EXPECT_NE(report.out.find("wrote " + out + "/report/" + name), std::string::npos) << report.out;
  }
  EXPECT_EQ(logs, 2);
  EXPECT_FALSE(fs::exists(out + "/report/ompl_lots"));
  EXPECT_FALSE(fs::exists(out + "/a.log"));
}

// The episode ids of a results table, in file order.
std::vector<std::string> ids(const std::string& jsonl) {
  std::vector<std::string> out;
  std::istringstream in(slurp(jsonl));
  for (std::string line; std::getline(in, line);) {
    out.push_back(nlohmann::json::parse(line)["episode_id"].get<std::string>());
  }
  return out;
}

TEST(ReportCli, DamagedEpisodeFoldersAreWarnedOfAndNotLinked) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml",
            testing::studySpec("seeds: [1, 2, 3, 4, 5]\n"
                               "record: {executed_csv: all, executed_rate_hz: 20}\n"));
  const std::string out = dir + "/out";
  ASSERT_EQ(runParksim("sweep " + dir + "/spec.yaml --out " + out + " -q").exit_code, 0);
  const std::vector<std::string> id = ids(out + "/results.jsonl");
  ASSERT_EQ(id.size(), 5u);
  const std::string episodes = out + "/episodes/";
  // Cut short (a full disk), deleted, garbage, emptied; the last one left whole.
  const std::string whole = slurp(episodes + id[0] + "/report.html");
  writeText(episodes + id[0] + "/report.html", whole.substr(0, whole.size() / 2));
  fs::remove(episodes + id[1] + "/report.html");
  writeText(episodes + id[2] + "/metrics.json", "\x7f\x45garbage");
  const std::string csv = slurp(episodes + id[3] + "/trajectory.csv");
  writeText(episodes + id[3] + "/trajectory.csv", csv.substr(0, csv.size() - 7));
  fs::resize_file(episodes + id[3] + "/executed.npz", 100);

  const auto report = runParksim("report " + out + " --junit " + dir + "/junit.xml");
  EXPECT_EQ(report.exit_code, 0) << report.out;
  const std::vector<std::string> expected = {
      episodes + id[0] + ": report.html is cut short or not a page",
      episodes + id[1] + ": report.html is missing",
      episodes + id[2] + ": metrics.json is not JSON",
      episodes + id[3] +
          ": executed.npz is cut short or not a zip archive; trajectory.csv is "
          "cut short"};
  const std::string page = slurp(out + "/report/index.html");
  for (const std::string& line : expected) {
    EXPECT_NE(report.out.find("warning: " + line + "\n"), std::string::npos) << report.out;
    EXPECT_NE(slurp(out + "/report/summary.md").find("- " + line + "\n"), std::string::npos);
    EXPECT_NE(page.find("\"" + line + "\""), std::string::npos) << line;  // the page's warnings
  }
  EXPECT_EQ(report.out.find("warning: " + episodes + id[4]), std::string::npos) << report.out;
  EXPECT_NE(report.out.find("\n4 warnings\n"), std::string::npos) << report.out;
  // Only whole pages are linked (JUnit's links are the page's: keptEpisodePage).
  const std::string junit = slurp(dir + "/junit.xml");
  for (int i : {0, 1}) EXPECT_EQ(junit.find(id[i] + "/report.html"), std::string::npos) << i;
  for (int i : {2, 3, 4}) EXPECT_NE(junit.find(id[i] + "/report.html"), std::string::npos) << i;
  // A sweep left whole has no warning.
  fs::remove_all(out + "/episodes");
  const auto clean = runParksim("report " + out);
  EXPECT_EQ(clean.exit_code, 0);
  EXPECT_EQ(clean.out.find("warning"), std::string::npos) << clean.out;
}

}  // namespace
}  // namespace parksim
