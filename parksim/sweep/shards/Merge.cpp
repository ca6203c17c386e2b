#include "parksim/sweep/shards/Merge.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include "parksim/core/io/Error.h"
#include "parksim/results/tables/ResultsFile.h"
#include "parksim/results/tables/RowSeal.h"
#include "parksim/sweep/shards/SweepManifest.h"
#include "parksim/sweep/spec/EpisodeParams.h"

namespace parksim {

namespace fs = std::filesystem;

namespace {

// What merge keeps per episode: where its first row is and what it holds (timing aside).
struct Seen {
  std::size_t source = 0;
  std::uint64_t offset = 0;
  std::size_t length = 0;
  std::uint64_t content = 0;
};

// Reads lines back from the merged sources by offset, a few files open at a time (a Slurm
// sweep may have thousands of shards).
class LineSource {
 public:
  explicit LineSource(const std::vector<std::string>& paths) : paths_(paths) {}
  ~LineSource() {
    for (const auto& [index, fd] : open_) ::close(fd);
  }
  LineSource(const LineSource&) = delete;
  LineSource& operator=(const LineSource&) = delete;

  // The line of `row`, checked again: a source changed since it was read is an error.
  const std::string& read(const MergedRow& row) {
    const int fd = fdOf(row.source);
    const std::string& path = paths_[row.source];
    line_.resize(row.length);
    std::size_t got = 0;
    while (got < row.length) {
      const ssize_t n =
          ::pread(fd, line_.data() + got, row.length - got, static_cast<off_t>(row.offset + got));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        throw Error(path + ": changed while it was merged (cannot read the row of episode " +
                    row.id + " again)");
      }
      got += static_cast<std::size_t>(n);
    }
    if (const std::optional<std::string> problem = sealProblem(line_)) {
      throw Error(path + ": changed while it was merged (episode " + row.id + "): " + *problem);
    }
    return line_;
  }

 private:
  int fdOf(std::size_t source) {
    if (const auto it = open_.find(source); it != open_.end()) return it->second;
    if (open_.size() >= 64) {
      ::close(open_.begin()->second);
      open_.erase(open_.begin());
    }
    const int fd = ::open(paths_[source].c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw Error(paths_[source] + ": cannot open: " + std::strerror(errno));
    open_.emplace(source, fd);
    return fd;
  }

  const std::vector<std::string>& paths_;
  std::map<std::size_t, int> open_;
  std::string line_;
};

}  // namespace

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
  const auto addManifest = [&](const std::string& dir) {
    SweepManifest manifest;
    if (readSweepManifest(dir, manifest)) {
      any_manifest = true;
      expected.insert(manifest.episode_ids.begin(), manifest.episode_ids.end());
    }
  };
  for (const std::string& dir : manifest_dirs) addManifest(dir);
  std::map<std::string, Seen> by_id;
  std::set<std::string> duplicated;
  std::set<std::string> conflicting;
  std::set<std::string, std::less<>> set_keys;
  TableOrigins origins;
  for (const std::string& dir : source_dirs) {
    addManifest(dir);
    const std::string path = dir + "/results.jsonl";
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      // A shard that never started has a manifest at most; its episodes show up as missing.
      if (any_manifest) continue;
      throw Error(path + ": no such file (not a sweep output directory)");
    }
    const std::size_t source = r.sources.size();
    r.sources.push_back(path);
    scanResultsJsonl(path, [&](const TableRow& t) {
      origins.add(t.row, path, t.line);
      addSetKeys(t.row, set_keys);
      const Seen seen{source, t.offset, t.text.size(), fnv1a64(withoutTiming(t.row).dump())};
      const auto [it, inserted] = by_id.emplace(t.row["episode_id"].get<std::string>(), seen);
      if (inserted) return;
      (it->second.content == seen.content ? duplicated : conflicting).insert(it->first);
    });
  }
  r.rows.reserve(by_id.size());
  for (const auto& [id, seen] : by_id) {
    r.rows.push_back(MergedRow{id, seen.source, seen.offset, seen.length});
  }
  r.duplicated.assign(duplicated.begin(), duplicated.end());
  r.conflicting.assign(conflicting.begin(), conflicting.end());
  r.mixes = origins.mixes();
  r.set_columns.assign(set_keys.begin(), set_keys.end());
  if (any_manifest) {
    r.expected = expected.size();
    for (const std::string& id : expected) {
      if (by_id.find(id) == by_id.end()) r.missing.push_back(id);
    }
    for (const auto& [id, seen] : by_id) {
      if (expected.find(id) == expected.end()) r.unexpected.push_back(id);
    }
  }
  return r;
}

void writeMergedTable(const std::string& dir, const MergeResult& merged) {
  LineSource lines(merged.sources);
  // The sources stay open (or are reopened) by descriptor or path: renaming the merged files
  // over a source only happens in commit(), after every line was read.
  ResultsTableWriter writer(dir, merged.set_columns);
  for (const MergedRow& row : merged.rows) {
    const std::string& line = lines.read(row);
    writer.add(line, nlohmann::ordered_json::parse(line));
  }
  writer.commit();
}

std::vector<nlohmann::ordered_json> mergedRows(const MergeResult& merged) {
  LineSource lines(merged.sources);
  std::vector<nlohmann::ordered_json> rows;
  rows.reserve(merged.rows.size());
  for (const MergedRow& row : merged.rows) {
    rows.push_back(nlohmann::ordered_json::parse(lines.read(row)));
  }
  return rows;
}

TableVerification verifyResults(const std::string& dir, std::size_t max_listed) {
  TableVerification v;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(dir + ": not a directory");
  const std::vector<std::string> sources = mergeSources(dir);
  const bool sharded = !(sources.size() == 1 && sources.front() == dir);
  // The whole sweep's ids are in the top folder's manifest (and a lone table's own).
  SweepManifest manifest;
  const bool has_manifest = readSweepManifest(dir, manifest);
  const std::vector<std::string>* expected = has_manifest ? &manifest.episode_ids : nullptr;
  if (sharded && fs::exists(dir + "/results.jsonl", ec)) verifyTable(dir, expected, max_listed, v);
  for (const std::string& source : sources) {
    if (fs::exists(source + "/results.jsonl", ec)) {
      verifyTable(source, sharded ? nullptr : expected, max_listed, v);
    }
  }
  if (v.tables.empty()) {
    throw Error(dir + ": no results table (results.jsonl) here" +
                (sharded ? std::string(" or in its shards/") : std::string()));
  }
  return v;
}

}  // namespace parksim
