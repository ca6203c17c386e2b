// `parksim report` over what users put in a sweep directory: worlds named with any text, and
// episode folders cut short, emptied or overwritten after the sweep.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace parksim
