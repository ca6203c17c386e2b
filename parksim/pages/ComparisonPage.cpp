#include "parksim/pages/ComparisonPage.h"

#include <filesystem>

#include "parksim/pages/PageDocument.h"
#include "parksim/pages/SweepPage.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

// The page of episode `id` of the sweep in `dir`, or an empty path.
fs::path episodePage(const std::string& dir, const std::string& id) {
  return dir.empty() ? fs::path() : keptEpisodePage((fs::path(dir) / "episodes").string(), id);
}

}  // namespace

nlohmann::json comparisonPageData(const ComparisonPage& page, const std::string& page_dir) {
  nlohmann::json data = page.comparison;
  data["page"] = "comparison";
  for (nlohmann::json& group : data["groups"]) {
    nlohmann::json linked = nlohmann::json::array();
    const nlohmann::json episodes = group.value("episodes", nlohmann::json::array());
    for (const nlohmann::json& e : episodes) {
      if (static_cast<int>(linked.size()) >= page.max_links_per_group) break;
      const std::string id = e.value("id", "");
      const fs::path b = episodePage(page.baseline_dir, id);
      const fs::path c = episodePage(page.candidate_dir, e.value("candidate_id", id));
      if (b.empty() || c.empty()) continue;
      nlohmann::json item = e;
      item["baseline_href"] = hrefOf(relativeHref(page_dir, b.string()));
      item["candidate_href"] = hrefOf(relativeHref(page_dir, c.string()));
      linked.push_back(std::move(item));
    }
    group["paired_episodes"] = episodes.size();
    group["linked_episodes"] = linked.size();
    group["episodes"] = std::move(linked);
  }
  return data;
}

void writeComparisonPage(const std::string& path, const ComparisonPage& page) {
  PageDocument doc;
  doc.title = "parksim compare: " +
              page.comparison.value("baseline", nlohmann::json::object())
                  .value("path", std::string("baseline")) +
              " vs " +
              page.comparison.value("candidate", nlohmann::json::object())
                  .value("path", std::string("candidate"));
  doc.libraries = {PageLibraryId::kTabulator};
  doc.scripts = {"summaries.js", "comparison.js"};
  const fs::path folder = fs::path(path).parent_path();
  doc.data = comparisonPageData(page, folder.empty() ? "." : folder.string());
  writePage(path, std::move(doc));
}

}  // namespace parksim
