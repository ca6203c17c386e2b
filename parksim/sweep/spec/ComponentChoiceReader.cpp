#include "parksim/sweep/spec/ComponentChoiceReader.h"

#include <algorithm>
#include <filesystem>

#include "parksim/core/params/ComponentRegistry.h"
#include "parksim/core/params/ParamSet.h"
#include "parksim/usercode/CommandLine.h"
#include "parksim/usercode/CommandPlanner.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

// A planners: or controllers: entry: a registered name; {command: [program, arg, ...]} (the
// `command` planner or controller, a program resolved against the spec's folder when it names a
// path); or {name: NAME} / the command, with params: {NAME: value, ...}, its own parameters.
ComponentChoice componentChoice(const YamlField& item, const std::string& base_dir,
                                const char* what) {
  ComponentChoice c;
  c.line = item.line();
  c.path = item.path();
  if (!item.node().IsMap()) {
    c.name = item.name();
    if (!isComponentName(c.name)) {
      item.fail("'" + c.name + "' is not a " + std::string(what) +
                "'s name (1 to 64 letters, digits, '-', '_' or '.')");
    }
    return c;
  }
  const YamlMap m = item.map({"name", "command", "params"});
  const auto name = m.optional("name");
  const auto command = m.optional("command");
  if (name.has_value() == command.has_value()) {
    item.fail("needs name: or command: (one of them)");
  }
  if (name) {
    c.name = name->name();
    if (!isComponentName(c.name)) {
      name->fail("'" + c.name + "' is not a " + std::string(what) +
                 "'s name (1 to 64 letters, digits, '-', '_' or '.')");
    }
  } else {
    c.name = kCommandPlanner;  // the command planner and the command controller share it
    std::vector<std::string> words;
    for (const YamlField& w : command->node().IsSequence() ? command->listUpTo(kMaxCommandWords)
                                                           : std::vector<YamlField>{*command}) {
      words.push_back(w.text());
    }
    if (!command->node().IsSequence()) words = splitCommandLine(words.front(), command->path());
    if (words.empty() || words.front().empty()) command->fail("names no program");
    // A program given as a path is the spec's neighbour, as worlds and plugins are.
    if (words.front().find('/') != std::string::npos && !fs::path(words.front()).is_absolute() &&
        !base_dir.empty()) {
      words.front() = (fs::path(base_dir) / words.front()).lexically_normal().string();
    }
    c.params[kCommandParam] = quoteCommandLine(words);
  }
  if (const auto params = m.optional("params")) {
    const YamlMap pm(*params);
    for (const std::string& key : pm.keys()) {
      const YamlField v = *pm.optional(key);
      if (!v.node().IsScalar()) v.fail("must be a number, true, false or a text");
      if (key == kCommandParam && command) v.fail("is given by command:");
      c.params[key] = canonicalParamText(v.text());
    }
  }
  return c;
}

}  // namespace

std::vector<ComponentChoice> componentsAxis(const std::vector<YamlField>& items,
                                            const std::string& base_dir, const char* what) {
  std::vector<ComponentChoice> out;
  for (const YamlField& item : items) {
    ComponentChoice c = componentChoice(item, base_dir, what);
    for (const ComponentChoice& earlier : out) {
      if (earlier.name == c.name && earlier.params == c.params) {
        item.fail("lists this " + std::string(what) + " a second time");
      }
    }
    out.push_back(std::move(c));
  }
  return out;
}

// plugins: paths of shared libraries, resolved against the spec's folder.
void readPlugins(const YamlField& field, const std::string& base_dir, SweepSpec& spec) {
  spec.plugins_line = field.line();
  for (const YamlField& item : field.listUpTo(64)) {
    const std::string written = item.text();
    const fs::path path = fs::path(written).is_absolute() || base_dir.empty()
                              ? fs::path(written)
                              : fs::path(base_dir) / written;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) item.fail("no such file: " + path.string());
    const std::string normal = fs::absolute(path, ec).lexically_normal().string();
    if (std::find(spec.plugin_paths.begin(), spec.plugin_paths.end(), normal) !=
        spec.plugin_paths.end()) {
      item.fail("lists " + written + " a second time");
    }
    spec.plugin_files.push_back(written);
    spec.plugin_paths.push_back(normal);
  }
}

}  // namespace parksim
