#include "parksim/compare/ComparedTable.h"

#include <filesystem>

#include "parksim/core/io/Error.h"
#include "parksim/results/tables/ResultsFile.h"
#include "parksim/sweep/shards/SweepManifest.h"

namespace parksim {

ComparedTable readComparedTable(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::string file = path;
  if (fs::is_directory(path, ec)) {
    SweepManifest manifest;
    (void)readSweepManifest(path, manifest);  // throws for another id format
    file = (fs::path(path) / "results.jsonl").string();
  }
  if (!fs::exists(file, ec)) {
    throw Error(file + ": no such file (a sweep directory or its results.jsonl is needed)");
  }
  if (!fs::is_regular_file(file, ec)) throw Error(file + ": not a regular file");
  VerifiedTable table = readVerifiedTable(file);
  if (table.rows.empty()) throw Error(file + ": no rows");
  return {std::move(table.rows), table.origins.mixes()};
}

}  // namespace parksim
