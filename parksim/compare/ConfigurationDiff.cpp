#include "parksim/compare/ConfigurationDiff.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "parksim/results/tables/EpisodeRecord.h"

namespace parksim {

namespace {

using Json = nlohmann::ordered_json;

bool configurationKey(const std::string& key) {
  if (key == "episode_id") return false;
  const EpisodeField* f = findField(key);
  if (f == nullptr) return isSetKey(key);
  return f->group == FieldGroup::kParameter || f->group == FieldGroup::kProvenance;
}

std::string valueText(const Json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

using Values = std::map<std::string, std::set<std::string>>;

// Every configuration column of `rows`, with its distinct values; and the columns in the order
// the rows first use them.
void collect(const std::vector<Json>& rows, Values& values, std::vector<std::string>& order) {
  for (const Json& row : rows) {
    for (const auto& [key, value] : row.items()) {
      if (!configurationKey(key)) continue;
      auto [it, added] = values.try_emplace(key);
      if (added && std::find(order.begin(), order.end(), key) == order.end()) order.push_back(key);
      it->second.insert(valueText(value));
    }
  }
}

std::string listed(const Values& values, const std::string& key) {
  const auto it = values.find(key);
  if (it == values.end()) return "(none)";
  std::string s;
  std::size_t n = 0;
  for (const std::string& v : it->second) {
    if (n == kMaxListedValues) {
      s += ", ... (" + std::to_string(it->second.size()) + " values)";
      break;
    }
    s += (n++ == 0 ? "" : ", ") + v;
  }
  return s;
}

std::vector<std::string> specLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    const std::size_t first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] == '#') continue;
    lines.push_back(line);
  }
  return lines;
}

}  // namespace

std::vector<ConfigurationDifference> columnDifferences(const std::vector<Json>& baseline,
                                                       const std::vector<Json>& candidate) {
  Values b;
  Values c;
  std::vector<std::string> order;
  collect(baseline, b, order);
  collect(candidate, c, order);
  std::vector<ConfigurationDifference> out;
  for (const std::string& key : order) {
    const auto ib = b.find(key);
    const auto ic = c.find(key);
    if (ib != b.end() && ic != c.end() && ib->second == ic->second) continue;
    out.push_back({key, listed(b, key), listed(c, key)});
  }
  return out;
}

std::vector<ConfigurationDifference> specDifferences(const std::string& baseline_text,
                                                     const std::string& candidate_text) {
  const std::vector<std::string> b = specLines(baseline_text);
  const std::vector<std::string> c = specLines(candidate_text);
  const std::multiset<std::string> in_b(b.begin(), b.end());
  const std::multiset<std::string> in_c(c.begin(), c.end());
  std::vector<ConfigurationDifference> out;
  for (const std::string& line : b) {
    if (in_c.count(line) == 0) out.push_back({"spec", line, ""});
  }
  for (const std::string& line : c) {
    if (in_b.count(line) == 0) out.push_back({"spec", "", line});
  }
  return out;
}

nlohmann::json differencesJson(const std::vector<ConfigurationDifference>& differences) {
  nlohmann::json out = nlohmann::json::array();
  for (const ConfigurationDifference& d : differences) {
    out.push_back({{"what", d.what}, {"baseline", d.baseline}, {"candidate", d.candidate}});
  }
  return out;
}

}  // namespace parksim
