#include "parksim/pages/JUnitPageLinks.h"

#include <filesystem>

#include "parksim/pages/SweepPage.h"

namespace parksim {

void linkJUnitToPages(JUnitReport& report, const std::string& junit_path,
                      const std::string& index_path, const std::string& episodes_dir) {
  const std::filesystem::path folder = std::filesystem::path(junit_path).parent_path();
  const std::string from = folder.empty() ? "." : folder.string();
  const std::string index = relativeHref(from, index_path);
  for (JUnitSuite& suite : report.suites) {
    suite.properties.push_back({"html_report", index});
    for (JUnitCase& c : suite.cases) {
      for (const JUnitProperty& p : c.properties) {
        if (p.name != "episode_id") continue;
        const std::filesystem::path page = keptEpisodePage(episodes_dir, p.value);
        if (!page.empty()) c.properties.push_back({"episode_report", relativeHref(from, page)});
        break;
      }
    }
  }
}

}  // namespace parksim
