#include "parksim/sweep/SweepManifest.h"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/core/InputFile.h"
#include "parksim/sweep/EpisodeParams.h"
#include "parksim/sweep/ResultsTable.h"

namespace parksim {

namespace {

// 2: episode ids of format 2 (EpisodeParams.h), recorded as episode_id_format.
const std::string kManifestFormat = "parksim-sweep-manifest/2";

}  // namespace

void writeSweepManifest(const std::string& dir, const SweepManifest& m) {
  nlohmann::ordered_json j;
  j["format"] = kManifestFormat;
  j["episode_id_format"] = kEpisodeIdFormat;
  j["spec"] = m.spec_path;
  j["name"] = m.name;
  j["shard"] = std::to_string(m.shard.index) + "/" + std::to_string(m.shard.count);
  j["episode_ids"] = m.episode_ids;
  ensureDirectory(dir);
  writeFileAtomically(dir + "/sweep.json", j.dump(1) + "\n");
}

bool readSweepManifest(const std::string& dir, SweepManifest& m) {
  const std::string path = dir + "/sweep.json";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return false;
  // A regular file within the results table's limit: a FIFO blocked the open, and keys of the
  // wrong type ended in a JSON type error (exit 3).
  const nlohmann::json j = nlohmann::json::parse(
      readInputFile(path, kMaxResultsTableBytes, "sweep manifest"), nullptr, false);
  if (j.is_object() && j.value("format", "") == "parksim-sweep-manifest/1") {
    throw Error(path +
                ": written by parksim 0.2, whose episode ids (format 1) left default "
                "parameters out and meant other defaults; this parksim's ids (format " +
                std::to_string(kEpisodeIdFormat) +
                ") spell every parameter: sweep into a new --out (docs/sweeps.md, \"Episode "
                "ids\")");
  }
  const Error not_manifest(path + ": not a sweep manifest (format " + kManifestFormat + ")");
  if (!j.is_object() || j.value("format", "") != kManifestFormat ||
      j.value("episode_id_format", 0) != kEpisodeIdFormat || !j.contains("episode_ids") ||
      !j["episode_ids"].is_array()) {
    throw not_manifest;
  }
  try {
    m.spec_path = j.value("spec", "");
    m.name = j.value("name", "");
    const std::string shard = j.value("shard", "0/1");
    m.shard = parseShard(shard);
    m.episode_ids = j["episode_ids"].get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception&) {
    throw not_manifest;
  }
  return true;
}

}  // namespace parksim
