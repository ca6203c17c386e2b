#include "parksim/sweep/Merge.h"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

#include "parksim/core/Error.h"
#include "parksim/sweep/ResultsTable.h"
#include "parksim/sweep/SweepManifest.h"

namespace parksim {

namespace fs = std::filesystem;

std::vector<std::string> mergeSources(const std::string& dir) {
  const fs::path shards = fs::path(dir) / "shards";
  std::error_code ec;
  if (!fs::is_directory(shards, ec)) return {dir};
  std::vector<std::pair<long, std::string>> found;
  for (const fs::directory_entry& e : fs::directory_iterator(shards)) {
    if (!e.is_directory()) continue;
    const std::string name = e.path().filename().string();
    char* end = nullptr;
    const long n = std::strtol(name.c_str(), &end, 10);
    // Numbered shard folders in numeric order, anything else after them by name.
    found.emplace_back(*end == '\0' && !name.empty() ? n : LONG_MAX, e.path().string());
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> out;
  for (const auto& [n, path] : found) out.push_back(path);
  return out;
}

MergeResult mergeResults(const std::vector<std::string>& source_dirs,
                         const std::vector<std::string>& manifest_dirs) {
  MergeResult r;
  std::set<std::string> expected;
  bool any_manifest = false;
  for (const std::string& dir : manifest_dirs) {
    SweepManifest manifest;
    if (readSweepManifest(dir, manifest)) {
      any_manifest = true;
      expected.insert(manifest.episode_ids.begin(), manifest.episode_ids.end());
    }
  }
  std::map<std::string, nlohmann::ordered_json> by_id;
  std::set<std::string> duplicated;
  std::set<std::string> conflicting;
  for (const std::string& dir : source_dirs) {
    SweepManifest manifest;
    if (readSweepManifest(dir, manifest)) {
      any_manifest = true;
      expected.insert(manifest.episode_ids.begin(), manifest.episode_ids.end());
    }
    const std::string path = dir + "/results.jsonl";
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      // A shard that never started has a manifest at most; its episodes show up as missing.
      if (any_manifest) continue;
      throw Error(path + ": no such file (not a sweep output directory)");
    }
    for (nlohmann::ordered_json& row : readResultsJsonl(path)) {
      const std::string id = row["episode_id"].get<std::string>();
      const auto it = by_id.find(id);
      if (it == by_id.end()) {
        by_id.emplace(id, std::move(row));
      } else if (withoutTiming(it->second) == withoutTiming(row)) {
        duplicated.insert(id);
      } else {
        conflicting.insert(id);
      }
    }
  }
  for (auto& [id, row] : by_id) r.rows.push_back(std::move(row));
  r.duplicated.assign(duplicated.begin(), duplicated.end());
  r.conflicting.assign(conflicting.begin(), conflicting.end());
  if (any_manifest) {
    r.expected = expected.size();
    for (const std::string& id : expected) {
      if (by_id.find(id) == by_id.end()) r.missing.push_back(id);
    }
    for (const auto& [id, row] : by_id) {
      if (expected.find(id) == expected.end()) r.unexpected.push_back(id);
    }
  }
  return r;
}

}  // namespace parksim
