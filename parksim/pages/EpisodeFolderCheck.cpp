#include "parksim/pages/EpisodeFolderCheck.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>
#include <string_view>

namespace parksim {

namespace fs = std::filesystem;

namespace {

// The first and last `n` bytes of a file (fewer when it is shorter); false when unreadable.
bool ends(const fs::path& path, std::size_t n, std::string& head, std::string& tail) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::size_t>(in.tellg());
  const std::size_t k = std::min(n, size);
  head.assign(k, '\0');
  tail.assign(k, '\0');
  in.seekg(0);
  in.read(head.data(), static_cast<std::streamsize>(k));
  in.seekg(static_cast<std::streamoff>(size - k));
  in.read(tail.data(), static_cast<std::streamsize>(k));
  return static_cast<bool>(in);
}

std::string fileProblem(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".json") {
    std::ifstream in(file, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return nlohmann::json::accept(text) ? "" : "is not JSON";
  }
  if (ext == ".csv") {
    std::string head;
    std::string tail;
    if (!ends(file, 1, head, tail) || tail.empty()) return "is empty";
    return tail == "\n" ? "" : "is cut short";
  }
  if (ext == ".npz") {
    // A zip archive without a comment (NumPy's, parksim's) ends with its 22-byte end record.
    std::string head;
    std::string tail;
    if (!ends(file, 22, head, tail) || tail.size() < 22) return "is cut short or not a zip archive";
    return tail.compare(0, 4, "PK\x05\x06") == 0 ? "" : "is cut short or not a zip archive";
  }
  return "";
}

}  // namespace

bool isWholePage(const fs::path& page) {
  static constexpr std::string_view kBegin = "<!DOCTYPE html>";
  static constexpr std::string_view kEnd = "</html>\n";
  std::error_code ec;
  if (!fs::is_regular_file(page, ec)) return false;
  std::string head;
  std::string tail;
  if (!ends(page, kBegin.size(), head, tail) || head != kBegin) return false;
  return tail.size() >= kEnd.size() &&
         tail.compare(tail.size() - kEnd.size(), kEnd.size(), kEnd) == 0;
}

std::string episodeFolderProblem(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return "not a folder";
  std::string problems;
  const auto add = [&problems](const std::string& p) {
    problems += (problems.empty() ? "" : "; ") + p;
  };
  const fs::path page = folder / "report.html";
  if (!fs::exists(page, ec)) {
    add("report.html is missing");
  } else if (!isWholePage(page)) {
    add("report.html is cut short or not a page");
  }
  // In name order, so that the line is the same on every file system.
  std::set<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (entry.is_regular_file(ec)) files.insert(entry.path());
  }
  for (const fs::path& file : files) {
    const std::string p = fileProblem(file);
    if (!p.empty()) add(file.filename().string() + " " + p);
  }
  return problems;
}

std::vector<std::string> episodeFolderProblems(const std::string& episodes_dir,
                                               const std::vector<nlohmann::ordered_json>& rows) {
  std::set<std::string> entries;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(episodes_dir, ec)) {
    entries.insert(entry.path().filename().string());
  }
  std::vector<std::string> lines;
  for (const nlohmann::ordered_json& row : rows) {
    const auto id = row.find("episode_id");
    if (id == row.end() || !id->is_string()) continue;
    const std::string& name = id->get_ref<const std::string&>();
    if (name.empty() || name == "." || name == ".." || entries.count(name) == 0) continue;
    const std::string problem = episodeFolderProblem(fs::path(episodes_dir) / name);
    if (!problem.empty()) lines.push_back(episodes_dir + "/" + name + ": " + problem);
  }
  return lines;
}

}  // namespace parksim
