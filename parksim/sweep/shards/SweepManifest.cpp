#include "parksim/sweep/shards/SweepManifest.h"

#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/spec/EpisodeParams.h"

namespace parksim {

namespace {

// 2: episode ids of format 2 or later (EpisodeParams.h), recorded as episode_id_format.
const std::string kManifestFormat = "parksim-sweep-manifest/2";

}  // namespace

void writeSweepManifest(const std::string& dir, const SweepManifest& m) {
  nlohmann::ordered_json j;
  j["format"] = kManifestFormat;
  j["episode_id_format"] = kEpisodeIdFormat;
  j["spec"] = m.spec_path;
  j["name"] = m.name;
  j["shard"] = std::to_string(m.shard.index) + "/" + std::to_string(m.shard.count);
  if (m.slurm_shards > 0) j["slurm_shards"] = m.slurm_shards;
  if (m.slurm_request) {
    const SlurmDef& r = *m.slurm_request;
    j["slurm_request"] = {{"cpus_per_task", r.cpus_per_task},
                          {"mem", r.mem},
                          {"time", r.time},
                          {"partition", r.partition},
                          {"account", r.account},
                          {"max_parallel", r.max_parallel}};
  }
  j["episode_ids"] = m.episode_ids;
  ensureDirectory(dir);
  writeFileAtomically(dir + "/sweep.json", j.dump(1) + "\n");
}

SweepManifest parseSweepManifest(std::string_view text, const std::string& path) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  const auto text_of = [&j](const char* key) -> std::optional<std::string> {
    const auto it = j.find(key);
    if (it == j.end() || !it->is_string()) return std::nullopt;
    return it->get<std::string>();
  };
  if (j.is_object() && text_of("format") == "parksim-sweep-manifest/1") {
    throw Error(path +
                ": written by parksim 0.2, whose episode ids (format 1) left default "
                "parameters out and meant other defaults; this parksim's ids (format " +
                std::to_string(kEpisodeIdFormat) +
                ") spell every parameter: sweep into a new --out (docs/sweeps.md, \"Episode "
                "ids\")");
  }
  const Error not_manifest(path + ": not a sweep manifest (format " + kManifestFormat + ")");
  // Every key checked for its type before it is read: a key of the wrong type was a JSON type
  // error (exit 3), a huge number an overflowing conversion.
  const auto whole = [&j](const char* key, long long lo, long long hi) -> std::optional<long long> {
    const auto it = j.find(key);
    if (it == j.end()) return std::nullopt;
    if (!it->is_number_integer()) return hi + 1;
    const long long v = it->is_number_unsigned() && it->get<std::uint64_t>() > std::uint64_t(hi)
                            ? hi + 1
                            : it->get<long long>();
    return v < lo ? hi + 1 : v;
  };
  if (!j.is_object() || text_of("format") != kManifestFormat) throw not_manifest;
  const std::optional<long long> id_format = whole("episode_id_format", 0, 1000);
  if (id_format && *id_format >= 2 && *id_format < kEpisodeIdFormat) {
    throw Error(path + ": written by an earlier parksim, whose episode ids (format " +
                std::to_string(*id_format) + ") hash other text than this parksim's (format " +
                std::to_string(kEpisodeIdFormat) +
                "): sweep into a new --out (docs/sweeps.md, \"Episode ids\")");
  }
  if (id_format != kEpisodeIdFormat) throw not_manifest;
  const auto ids = j.find("episode_ids");
  if (ids == j.end() || !ids->is_array()) throw not_manifest;
  SweepManifest m;
  for (const nlohmann::json& id : *ids) {
    if (!id.is_string()) throw not_manifest;
    m.episode_ids.push_back(id.get<std::string>());
  }
  for (const char* key : {"spec", "name", "shard"}) {
    if (j.contains(key) && !text_of(key)) throw not_manifest;
  }
  m.spec_path = text_of("spec").value_or("");
  m.name = text_of("name").value_or("");
  try {
    m.shard = parseShard(text_of("shard").value_or("0/1"));
  } catch (const Error&) {
    throw not_manifest;
  }
  const std::optional<long long> shards = whole("slurm_shards", 0, 100000);
  if (shards && *shards > 100000) throw not_manifest;
  m.slurm_shards = static_cast<int>(shards.value_or(0));
  if (const auto r = j.find("slurm_request"); r != j.end()) {
    // Every field present and of its type; the words are checked again where the script is
    // written (sbatchScript), so a changed file cannot put a line of its own into the script.
    const auto word = [&](const char* key) -> std::string {
      const auto it = r->find(key);
      if (it == r->end() || !it->is_string()) throw not_manifest;
      return it->get<std::string>();
    };
    if (!r->is_object()) throw not_manifest;
    const auto cpus = r->find("cpus_per_task");
    if (cpus == r->end() || !cpus->is_number_integer() || *cpus < 1 || *cpus > 1024) {
      throw not_manifest;
    }
    SlurmDef d;
    d.cpus_per_task = cpus->get<int>();
    d.mem = word("mem");
    d.time = word("time");
    d.partition = word("partition");
    d.account = word("account");
    d.max_parallel = word("max_parallel");
    m.slurm_request = d;
  }
  return m;
}

bool readSweepManifest(const std::string& dir, SweepManifest& m) {
  const std::string path = dir + "/sweep.json";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return false;
  // A regular file within the results table's limit: a FIFO blocked the open.
  m = parseSweepManifest(readInputFile(path, kMaxResultsTableBytes, "sweep manifest"), path);
  return true;
}

}  // namespace parksim
