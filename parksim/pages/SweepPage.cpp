#include "parksim/pages/SweepPage.h"

#include <filesystem>
#include <unordered_set>

#include "parksim/core/io/Error.h"
#include "parksim/pages/ColumnCodec.h"
#include "parksim/pages/EpisodeFolderCheck.h"
#include "parksim/pages/PageDocument.h"
#include "parksim/pages/TableColumns.h"
#include "parksim/results/tables/EpisodeRecord.h"

namespace parksim {

std::vector<std::string> parameterColumns(const std::vector<nlohmann::ordered_json>& rows) {
  std::vector<std::string> axes;
  if (rows.empty()) return axes;
  for (const auto& [key, value] : rows.front().items()) {
    if (key == "status") break;
    if (key != "episode_id" && !isReplicateKey(key)) axes.push_back(key);
  }
  return axes;
}

std::filesystem::path keptEpisodePage(const std::string& episodes_dir, const std::string& id) {
  namespace fs = std::filesystem;
  if (id.empty() || id == "." || id == ".." || id.find_first_of("/\\") != std::string::npos) {
    return {};
  }
  const fs::path page = fs::path(episodes_dir) / id / "report.html";
  return isWholePage(page) ? page : fs::path();
}

std::vector<bool> keptEpisodePages(const std::string& episodes_dir,
                                   const std::vector<nlohmann::ordered_json>& rows) {
  // The folders there, listed once: most episodes of a large sweep keep none, and asking for
  // each id's page would cost a failed lookup per row.
  std::unordered_set<std::string> folders;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(episodes_dir, ec)) {
    folders.insert(entry.path().filename().string());
  }
  std::vector<bool> kept;
  kept.reserve(rows.size());
  for (const nlohmann::ordered_json& row : rows) {
    const auto id = row.find("episode_id");
    kept.push_back(id != row.end() && id->is_string() &&
                   folders.count(id->get_ref<const std::string&>()) > 0 &&
                   !keptEpisodePage(episodes_dir, id->get<std::string>()).empty());
  }
  return kept;
}

std::string relativeHref(const std::string& from, const std::string& to) {
  namespace fs = std::filesystem;
  const fs::path a = fs::absolute(fs::path(from)).lexically_normal();
  const fs::path b = fs::absolute(fs::path(to)).lexically_normal();
  fs::path rel = b.lexically_relative(a);
  if (rel.empty()) rel = b;
  return rel.generic_string();
}

std::string hrefOf(std::string_view path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string href;
  href.reserve(path.size());
  for (const char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    const bool kept = (byte >= 'A' && byte <= 'Z') || (byte >= 'a' && byte <= 'z') ||
                      (byte >= '0' && byte <= '9') || c == '-' || c == '.' || c == '_' ||
                      c == '~' || c == '/';
    if (kept) {
      href += c;
    } else {
      href += '%';
      href += kHex[byte >> 4];
      href += kHex[byte & 15];
    }
  }
  return href;
}

nlohmann::json sweepPageData(const SweepPage& page) {
  if (page.rows == nullptr) throw Error("sweepPageData: no rows");
  if (!page.kept.empty() && page.kept.size() != page.rows->size()) {
    throw Error("sweepPageData: kept has " + std::to_string(page.kept.size()) + " flags for " +
                std::to_string(page.rows->size()) + " rows");
  }
  std::vector<std::uint32_t> kept(page.rows->size(), 0);
  for (std::size_t i = 0; i < page.kept.size(); ++i) kept[i] = page.kept[i] ? 1 : 0;
  nlohmann::json episodes = {{"href", page.episodes_href}, {"kept", codeColumn(kept, 2)}};
  return {{"page", "sweep"},
          {"title", page.title},
          {"source", page.source},
          {"table", tableColumns(*page.rows)},
          {"axes", page.axes},
          {"statuses", page.statuses},
          {"episodes", std::move(episodes)},
          {"warnings", page.warnings}};
}

void writeSweepPage(const std::string& path, const SweepPage& page) {
  PageDocument doc;
  doc.title = "parksim sweep: " + page.title;
  doc.libraries = {PageLibraryId::kTabulator, PageLibraryId::kUPlot};
  doc.scripts = {"summaries.js", "sweep.js"};
  doc.data = sweepPageData(page);
  writePage(path, std::move(doc));
}

}  // namespace parksim
