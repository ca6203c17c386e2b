#include "parksim/results/episode/JsonFile.h"

#include <fstream>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"

namespace parksim {

nlohmann::json provenanceToJson(const Provenance& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, value] : provenanceFields(p)) j[key] = value;
  j["git_dirty"] = p.git_dirty;
  return j;
}

void writeJsonFile(const std::string& path, const nlohmann::json& json) {
  writeFileAtomically(path, jsonText(json));
}

nlohmann::json readJsonFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw Error(path + ": not valid JSON: " + e.what());
  }
}

std::string jsonText(const nlohmann::json& j) {
  // Names and paths from input files need not be UTF-8: their bad bytes become U+FFFD.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace parksim
