#include "parksim/scenario/world/ScenarioOverrides.h"

#include <algorithm>
#include <cctype>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/scenario/world/WorldDocument.h"

namespace parksim {

namespace {

struct PathStep {
  std::string key;        // map key, or empty for a list index
  std::size_t index = 0;  // list index when key is empty
  std::string path;       // the path up to and including this step, for messages
};

std::vector<PathStep> splitPath(const ScenarioOverride& o) {
  std::vector<PathStep> steps;
  std::string path;
  std::size_t i = 0;
  const std::string& p = o.path;
  auto bad = [&o](const std::string& why) -> Error {
    return Error(o.label + ": bad field path '" + o.path + "': " + why);
  };
  if (p.empty()) throw bad("empty");
  while (i < p.size()) {
    if (p[i] == '[') {
      const std::size_t close = p.find(']', i);
      if (close == std::string::npos) throw bad("'[' without ']'");
      long long index = -1;
      if (!parseInt(std::string_view(p).substr(i + 1, close - i - 1), index) || index < 0) {
        throw bad("list index must be a whole number >= 0");
      }
      path += p.substr(i, close - i + 1);
      steps.push_back({"", static_cast<std::size_t>(index), path});
      i = close + 1;
      if (i < p.size() && p[i] == '.') ++i;
      continue;
    }
    const std::size_t end = p.find_first_of(".[", i);
    const std::string key = p.substr(i, end == std::string::npos ? std::string::npos : end - i);
    if (key.empty()) throw bad("empty key");
    if (key.find(']') != std::string::npos) throw bad("']' without '['");
    path += (path.empty() ? "" : ".") + key;
    steps.push_back({key, 0, path});
    if (end == std::string::npos) break;
    i = p[end] == '.' ? end + 1 : end;
    if (p[end] == '.' && i == p.size()) throw bad("ends with '.'");
  }
  return steps;
}

YAML::Node parseValue(const ScenarioOverride& o) {
  try {
    return YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw Error(o.label + ": (syntax): " + e.msg);
  }
}

}  // namespace

void applyOverride(YAML::Node& document, const ScenarioOverride& o) {
  const std::vector<PathStep> steps = splitPath(o);
  const YAML::Node value = parseValue(o);
  YAML::Node node = document;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const PathStep& step = steps[s];
    const bool last = s + 1 == steps.size();
    const std::string parent = s == 0 ? std::string("(document)") : steps[s - 1].path;
    if (!step.key.empty()) {
      if (node.IsNull()) node = YAML::Node(YAML::NodeType::Map);  // a section left empty
      if (!node.IsMap()) throw Error(o.label + ": " + parent + ": is not a map");
      if (last) {
        node[step.key] = value;
        return;
      }
      // A section the file leaves out is created; the reader then checks its keys as usual.
      if (!node[step.key]) node[step.key] = YAML::Node(YAML::NodeType::Map);
      node.reset(node[step.key]);
    } else {
      if (!node.IsSequence()) throw Error(o.label + ": " + parent + ": is not a list");
      if (step.index >= node.size()) {
        throw Error(o.label + ": " + step.path + ": " + parent + " has " +
                    std::to_string(node.size()) + " item" + (node.size() == 1 ? "" : "s"));
      }
      if (last) {
        node[step.index] = value;
        return;
      }
      node.reset(node[step.index]);
    }
  }
}

namespace {

// Text YAML reads as a plain scalar of exactly that text (a number, a name): letters, digits,
// '.', '_', '+', and '-' other than as a list's dash. Anything else goes through the parser.
bool isPlainWord(std::string_view t) {
  if (t.empty() ||
      (t[0] == '-' &&
       (t.size() == 1 || !(std::isdigit(static_cast<unsigned char>(t[1])) || t[1] == '.')))) {
    return false;
  }
  return std::all_of(t.begin(), t.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_' || c == '+' ||
           c == '-';
  });
}

}  // namespace

bool replaceScalar(YAML::Node& document, const ScenarioOverride& o) {
  // A sweep sets numbers per episode: those skip the parser (a fifth of a world's read).
  const bool plain = isPlainWord(o.value);
  const YAML::Node value = plain ? YAML::Node() : parseValue(o);
  if (!plain && !value.IsScalar()) return false;
  const std::string& text = plain ? o.value : value.Scalar();
  const std::string tag = plain ? std::string("?") : value.Tag();
  YAML::Node node = document;
  for (const PathStep& step : splitPath(o)) {
    // Looked up through a const node: a missing key is not created.
    const YAML::Node& here = node;
    if (!step.key.empty()) {
      if (!here.IsMap() || !here[step.key]) return false;
      node.reset(here[step.key]);
    } else {
      if (!here.IsSequence() || step.index >= here.size()) return false;
      node.reset(here[step.index]);
    }
  }
  if (!node.IsScalar() || node.Tag() != tag) return false;
  node = text;
  return true;
}

namespace {

bool startsWithField(std::string_view text, std::string_view path) {
  if (text.substr(0, path.size()) != path || text.size() == path.size()) return false;
  const char next = text[path.size()];
  return next == ':' || next == '.' || next == '[';
}

}  // namespace

[[noreturn]] void rethrowNamingOverride(const Error& e, const std::string& source,
                                        const std::vector<ScenarioOverride>& overrides) {
  const std::string_view message = e.what();
  if (message.substr(0, source.size() + 1) == source + ":") {
    std::string_view rest = message.substr(source.size() + 1);
    const std::size_t digits = rest.find_first_not_of("0123456789");
    if (digits != 0 && digits != std::string_view::npos && rest.substr(digits, 2) == ": ") {
      rest.remove_prefix(digits + 2);
      for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
        if (startsWithField(rest, it->path)) throw Error(it->label + ": " + std::string(rest));
      }
    }
  }
  throw e;
}

}  // namespace parksim
