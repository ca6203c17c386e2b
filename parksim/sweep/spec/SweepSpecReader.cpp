#include "parksim/sweep/spec/SweepSpecReader.h"

#include <glob.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/params/ParamSet.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/tree/TreePlanner.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/scenario/yaml/YamlField.h"
#include "parksim/sim/episode/ExecutionDef.h"
#include "parksim/sweep/spec/ComponentChoiceReader.h"
#include "parksim/sweep/spec/EpisodeSetup.h"
#include "parksim/sweep/spec/SetValues.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kFormat = "parksim-sweep/1";
// A sweep is meant to finish; a typo such as `to: 1e9` should not start a billion episodes.
constexpr std::size_t kMaxEpisodes = 10'000'000;
// A spec is a page of YAML; /dev/zero or a huge file must not be read into memory.
constexpr std::uintmax_t kMaxSpecBytes = 1 << 20;
// As --max-iterations (docs/limits.md): the tree and its edges stay in memory.
constexpr int kMaxSpecIterations = 1'000'000;

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

// A scalar is an axis of one value; a list gives several (at least one).
std::vector<YamlField> axisItems(const YamlField& field) {
  if (field.node().IsScalar()) return {field};
  if (!field.node().IsSequence()) field.fail("must be a value or a list of values");
  std::vector<YamlField> items = field.items();
  if (items.empty()) field.fail("must list at least one value");
  return items;
}

// Each value once: a repeated value would run the same episodes twice under one id.
template <typename T>
void rejectDuplicates(const std::vector<YamlField>& items, const std::vector<T>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (values[i] == values[j]) items[i].fail("repeats " + items[j].path());
    }
  }
}

std::vector<std::string> namesAxis(const YamlField& field, const std::vector<std::string>& known,
                                   const std::string& what, const std::string& later = "") {
  const std::vector<YamlField> items = axisItems(field);
  std::vector<std::string> values;
  for (const YamlField& item : items) {
    const std::string v = item.text();
    if (std::find(known.begin(), known.end(), v) == known.end()) {
      item.fail("unknown " + what + " '" + v + "' (this build has: " + joined(known) + ")" + later);
    }
    values.push_back(v);
  }
  rejectDuplicates(items, values);
  return values;
}

// A seed is any 64-bit value, as --seed takes. Digits are read as an integer: through a double,
// 9007199254740993 became ...992, another seed, without a word. A whole number in another
// spelling (1e3, 20.0) is read as a double, where it is exact (up to 2^53).
std::uint64_t seedValue(const YamlField& field) {
  const YAML::Node& node = field.node();
  if (node.IsScalar() && node.Tag() == "?") {
    const std::string& text = node.Scalar();
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc() && end == text.data() + text.size()) return value;
  }
  const double v = field.number();
  if (v < 0.0 || v != std::floor(v) || v > 9007199254740992.0) {
    field.fail("must be a whole number in [0, 18446744073709551615] (above 2^53 in digits), got " +
               node.Scalar());
  }
  return static_cast<std::uint64_t>(v);
}

// A list of seeds, one seed, or {from: A, to: B} (both included).
std::vector<std::uint64_t> seedsAxis(const YamlField& field) {
  if (field.node().IsMap()) {
    const YamlMap m = field.map({"from", "to"});
    const std::uint64_t from = seedValue(m.required("from"));
    const YamlField to_field = m.required("to");
    const std::uint64_t to = seedValue(to_field);
    if (to < from) to_field.fail("must be at least from (" + std::to_string(from) + ")");
    if (to - from >= kMaxEpisodes) to_field.fail("range too large");
    std::vector<std::uint64_t> seeds;
    // Counted, not `s <= to`: that never ends when `to` is the largest seed.
    for (std::uint64_t k = 0; k <= to - from; ++k) seeds.push_back(from + k);
    return seeds;
  }
  const std::vector<YamlField> items = axisItems(field);
  std::vector<std::uint64_t> values;
  for (const YamlField& item : items) values.push_back(seedValue(item));
  rejectDuplicates(items, values);
  return values;
}

std::vector<PoseOffset> offsetsAxis(const YamlField& field, std::vector<int>& lines) {
  if (!field.node().IsSequence()) {
    field.fail("must be a list of [dx_m, dy_m, dyaw_deg] offsets, e.g. [[0, 0, 0], [0.01, 0, 0]]");
  }
  const std::vector<YamlField> items = field.items();
  if (items.empty()) field.fail("must list at least one offset");
  std::vector<PoseOffset> values;
  lines.clear();
  for (const YamlField& item : items) {
    const std::vector<double> v = item.numbers(3, "[dx_m, dy_m, dyaw_deg]");
    values.push_back({v[0], v[1], v[2]});
    lines.push_back(item.line());
  }
  rejectDuplicates(items, values);
  return values;
}

// Combinations the set: axes add: the grid's values times the samples drawn.
double setCombinations(const SweepSpec& spec) {
  double n = spec.samples ? static_cast<double>(spec.samples->count) : 1.0;
  for (const SetAxis& a : spec.set)
    n *= a.distribution ? 1.0 : static_cast<double>(a.values.size());
  return n;
}

bool hasGlobChars(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

void readWorlds(const YamlField& field, const std::string& base_dir, SweepSpec& spec) {
  spec.worlds_line = field.line();
  for (const YamlField& item : axisItems(field)) {
    const std::string pattern = item.text();
    const fs::path base = base_dir.empty() ? fs::path() : fs::path(base_dir);
    const fs::path resolved = fs::path(pattern).is_absolute() ? fs::path(pattern) : base / pattern;
    std::vector<std::string> matches;
    if (hasGlobChars(pattern)) {
      glob_t g{};
      const int rc = glob(resolved.string().c_str(), 0, nullptr, &g);
      if (rc == 0) {
        for (std::size_t i = 0; i < g.gl_pathc; ++i) matches.emplace_back(g.gl_pathv[i]);
      }
      globfree(&g);
      if (matches.empty()) item.fail("matches no file (" + resolved.string() + ")");
      std::sort(matches.begin(), matches.end());
    } else {
      std::error_code ec;
      if (!fs::is_regular_file(resolved, ec)) item.fail("no such file: " + resolved.string());
      matches.push_back(resolved.string());
    }
    for (const std::string& path : matches) {
      const std::string normal = fs::path(path).lexically_normal().string();
      // Written relative to the spec's folder, so the column reads the same wherever the
      // sweep runs (locally, on a cluster node, from another working directory).
      const std::string shown = fs::path(pattern).is_absolute()
                                    ? normal
                                    : fs::path(path).lexically_relative(base).string();
      if (std::find(spec.world_paths.begin(), spec.world_paths.end(), normal) !=
          spec.world_paths.end()) {
        item.fail("lists " + shown + " a second time");
      }
      spec.world_paths.push_back(normal);
      spec.world_files.push_back(base_dir.empty() ? normal : fs::path(shown).string());
    }
  }
}

// The field's text through the library's own parser of those names; its message, at the
// field's line.
template <class Parse>
auto parsedBy(const YamlField& f, Parse parse) {
  try {
    return parse(f.text());
  } catch (const Error& e) {
    f.fail(e.what());
  }
}

void readRecord(const YamlField& field, SweepRecordDef& r) {
  const YamlMap m =
      field.map({"executed_csv", "executed_rate_hz", "format", "film_failures", "film"});
  if (const std::optional<YamlField> f = m.optional("executed_csv")) {
    r.executed_csv = parsedBy(*f, filesPolicyFromString);
  }
  if (const std::optional<YamlField> f = m.optional("executed_rate_hz")) {
    r.executed_rate_hz = f->positive();
  }
  if (const std::optional<YamlField> f = m.optional("format")) {
    r.format = parsedBy(*f, recordFormatFromString);
  }
  if (const std::optional<YamlField> f = m.optional("film_failures")) {
    r.film_failures = f->boolean();
  }
  if (const std::optional<YamlField> f = m.optional("film")) {
    const YamlMap film = f->map({"fps", "size", "view", "video"});
    if (const std::optional<YamlField> g = film.optional("fps")) {
      // As run --fps (docs/limits.md): 1e9 fps rendered frames until the 50,000-frame limit.
      r.film_fps = g->positive();
      if (r.film_fps > 1000.0)
        g->fail("must be in (0, 1000] frames per second, got " + g->node().Scalar());
    }
    if (const std::optional<YamlField> g = film.optional("size")) {
      const std::string text = g->text();
      int w = 0;
      int h = 0;
      char x = 0;
      char extra = 0;
      std::istringstream in(text);
      if (!(in >> w >> x >> h) || x != 'x' || (in >> extra) || w < 16 || h < 16 || w > 8192 ||
          h > 8192) {
        g->fail("must be WxH, each 16..8192, e.g. 640x480; got '" + text + "'");
      }
      r.film_width_px = w;
      r.film_height_px = h;
    }
    if (const std::optional<YamlField> g = film.optional("view")) {
      const std::string v = g->text();
      if (v != "top" && v != "3d" && v != "both") {
        g->fail("must be top, 3d or both, got '" + v + "'");
      }
      r.film_view = v;
    }
    if (const std::optional<YamlField> g = film.optional("video")) r.film_video = g->boolean();
  }
}

void readTolerance(const YamlField& field, ToleranceOverrides& t) {
  const YamlMap m = field.map({"max_pos_err_m", "goal_pos_err_m", "goal_heading_err_deg",
                               "max_contacts", "max_parked_displacement_m"});
  if (const std::optional<YamlField> f = m.optional("max_pos_err_m"))
    t.max_pos_err_m = f->positive();
  if (const std::optional<YamlField> f = m.optional("goal_pos_err_m")) {
    t.goal_pos_err_m = f->positive();
  }
  if (const std::optional<YamlField> f = m.optional("goal_heading_err_deg")) {
    t.goal_heading_err_deg = f->positive();
  }
  if (const std::optional<YamlField> f = m.optional("max_contacts")) {
    const std::uint64_t n = seedValue(*f);
    if (n > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      f->fail("must be at most " + std::to_string(std::numeric_limits<int>::max()));
    }
    t.max_contacts = static_cast<int>(n);
  }
  if (const std::optional<YamlField> f = m.optional("max_parked_displacement_m")) {
    t.max_parked_displacement_m = f->nonNegative();
  }
}

// Deep enough for any world value (a pose, a polygon's points); bounds a hostile spec.
constexpr int kMaxValueDepth = 8;

// A scalar's canonical text (SetValues.h): a number in its shortest round-trip form, true or
// false, other text as written.
std::string canonicalScalar(const YamlField& f) {
  const std::string& text = f.node().Scalar();
  if (text.empty()) f.fail("must not be empty");
  double v = 0.0;
  if (parseDouble(text, v)) {
    if (!std::isfinite(v)) f.fail("must be a finite number, got " + text);
    return canonicalNumber(v);
  }
  return text;
}

nlohmann::ordered_json canonicalJson(const YamlField& f, int depth) {
  if (depth > kMaxValueDepth) f.fail("is nested too deeply for a world value");
  if (f.node().IsScalar()) return setValueJson(canonicalScalar(f));
  if (f.node().IsSequence()) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const YamlField& item : f.items()) list.push_back(canonicalJson(item, depth + 1));
    return list;
  }
  if (f.node().IsMap()) {
    const YamlMap m(f);
    std::vector<std::string> keys = m.keys();
    std::sort(keys.begin(), keys.end());  // the world reader does not care; ids would
    nlohmann::ordered_json map = nlohmann::ordered_json::object();
    for (const std::string& k : keys) map[k] = canonicalJson(*m.optional(k), depth + 1);
    return map;
  }
  f.fail("must be a value");
}

// One value of a set: axis as canonical text: scalars as they are, lists and maps as compact
// JSON. Planner and controller parameters take scalars only.
std::string canonicalValue(const YamlField& f, bool scalar_only) {
  if (f.node().IsScalar()) return canonicalScalar(f);
  if (scalar_only) f.fail("must be a number, true, false or text (a parameter's value)");
  return canonicalJson(f, 0).dump();
}

bool isIdentifier(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  });
}

// The path of a set: axis, checked for what the spec can tell without the worlds (the world
// reader checks the rest, per world, when the episodes are expanded).
void checkSetPath(const YamlField& key_field, const std::string& path) {
  const auto bad = [&](const std::string& why) { key_field.fail(why); };
  if (path.empty()) bad("an empty path");
  if (!std::all_of(path.begin(), path.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' ||
               c == '[' || c == ']';
      })) {
    bad("a path is keys joined by '.' and list items as [i], e.g. robot.max_wheel_speed_radps "
        "or obstacles[2].center");
  }
  const std::string root = path.substr(0, path.find_first_of(".["));
  if (root == "planner" || root == "controller") {
    if (path.size() <= root.size() + 1 || path[root.size()] != '.' ||
        !isIdentifier(std::string_view(path).substr(root.size() + 1))) {
      bad(root + " parameters are " + root + ".NAME, NAME of letters, digits and _");
    }
    return;
  }
  if (root == "name" || root == "format") {
    bad("the world's " + root + " is not a value to vary (episode ids name the world by it)");
  }
  if (!isSetKey(path)) {
    bad("'" + path + "' is a column of the results table; set the fields inside it (e.g. " + path +
        ".FIELD)");
  }
}

// {uniform: [a, b]}, {normal: [mean, sd]} or {choice: [...]}.
SetDistribution readDistribution(const YamlField& field, bool scalar_only) {
  const YamlMap m = field.map({"uniform", "normal", "choice"});
  const std::vector<std::string> keys = m.keys();
  if (keys.size() != 1) field.fail("a distribution is one of uniform, normal or choice");
  const YamlField f = *m.optional(keys.front());
  SetDistribution d;
  if (keys.front() == "choice") {
    d.kind = SetDistribution::Kind::kChoice;
    if (!f.node().IsSequence() || f.items().empty()) f.fail("must list at least one value");
    const std::vector<YamlField> items = f.items();
    for (const YamlField& item : items) d.choices.push_back(canonicalValue(item, scalar_only));
    rejectDuplicates(items, d.choices);
    return d;
  }
  const bool uniform = keys.front() == "uniform";
  d.kind = uniform ? SetDistribution::Kind::kUniform : SetDistribution::Kind::kNormal;
  const std::vector<double> v = f.numbers(2, uniform ? "[low, high]" : "[mean, sd]");
  d.a = v[0];
  d.b = v[1];
  if (uniform && !(d.a < d.b)) f.fail("the low end must be below the high end");
  if (!uniform && !(d.b > 0.0)) f.fail("the standard deviation must be positive");
  return d;
}

void readSet(const YamlField& field, SweepSpec& spec) {
  const YamlMap m(field);
  for (const std::string& path : m.keys()) {
    const YamlField value = *m.optional(path);
    checkSetPath(value, path);
    SetAxis axis;
    axis.path = path;
    axis.line = value.line();
    const bool scalar_only = axis.target() != SetAxis::Target::kWorld;
    if (value.node().IsMap()) {
      axis.distribution = readDistribution(value, scalar_only);
    } else {
      const std::vector<YamlField> items = axisItems(value);
      for (const YamlField& item : items) axis.values.push_back(canonicalValue(item, scalar_only));
      rejectDuplicates(items, axis.values);
    }
    // The parameters of planner.NAME and controller.NAME axes belong to the selected planner
    // or controller, which validates them: when the spec expands, against the planners and
    // controllers the spec's plugins bring (EpisodeExpansion.cpp, checkComponents).
    spec.set.push_back(std::move(axis));
  }
  std::sort(spec.set.begin(), spec.set.end(),
            [](const SetAxis& a, const SetAxis& b) { return a.path < b.path; });
}

void readSamples(const YamlField& field, SweepSpec& spec) {
  const YamlMap m = field.map({"count", "seed"});
  const YamlField count = m.required("count");
  const std::uint64_t n = seedValue(count);
  if (n < 1 || n > kMaxEpisodes) {
    count.fail("must be in [1, " + std::to_string(kMaxEpisodes) + "], got " +
               count.node().Scalar());
  }
  spec.samples = SampleDef{n, seedValue(m.required("seed"))};
  spec.samples_line = field.line();
}

}  // namespace

SweepSpec parseSweepSpec(std::string_view yaml_text, const std::string& source_name,
                         const std::string& base_dir) {
  const YAML::Node document =
      loadSingleYamlDocument(std::string(yaml_text), source_name, "sweep spec", kFormat);
  const YamlField root(document, "", 1, source_name);
  const YamlMap top(root);
  const YamlField format = top.required("format");
  if (format.text() != kFormat) {
    format.fail("expected \"" + std::string(kFormat) + "\", got \"" + format.text() + "\"");
  }
  top.rejectUnknownKeys({"format",        "name",         "worlds",  "planners",
                         "steering",      "smoothing",    "seeds",   "max_iterations",
                         "tracking",      "timing",       "realism", "noise_seeds",
                         "start_offsets", "goal_offsets", "set",     "samples",
                         "record",        "tolerance",    "plugins", "controllers"});

  SweepSpec spec;
  spec.source_path = source_name;
  // name(): UTF-8 without control characters; it reaches the terminal, reports and job names.
  spec.name = top.required("name").name();
  readWorlds(top.required("worlds"), base_dir, spec);

  if (const auto f = top.optional("plugins")) readPlugins(*f, base_dir, spec);
  std::vector<std::string> steering_names;
  for (SteeringKind k : allSteeringKinds()) steering_names.emplace_back(toString(k));
  if (const auto f = top.optional("planners")) {
    spec.planners = componentsAxis(axisItems(*f), base_dir, "planner");
  }
  if (const auto f = top.optional("controllers")) {
    spec.controllers = componentsAxis(axisItems(*f), base_dir, "controller");
  }
  if (const auto f = top.optional("steering")) {
    spec.steerings = namesAxis(*f, steering_names, "steering");
  }
  if (const auto f = top.optional("smoothing")) {
    const std::vector<YamlField> items = axisItems(*f);
    spec.smoothing.clear();
    for (const YamlField& item : items) spec.smoothing.push_back(item.boolean());
    rejectDuplicates(items, spec.smoothing);
  }
  if (const auto f = top.optional("seeds")) spec.seeds = seedsAxis(*f);
  if (const auto f = top.optional("max_iterations")) {
    const std::vector<YamlField> items = axisItems(*f);
    spec.max_iterations.clear();
    for (const YamlField& item : items) {
      // "auto": the lot's budget, as --max-iterations auto.
      if (item.node().IsScalar() && item.node().Scalar() == "auto") {
        spec.max_iterations.push_back(kAutoIterations);
        continue;
      }
      const int n = item.positiveInt();
      if (n > kMaxSpecIterations) {
        item.fail("must be auto or an integer in [1, " + std::to_string(kMaxSpecIterations) +
                  "], got " + item.node().Scalar());
      }
      spec.max_iterations.push_back(n);
    }
    rejectDuplicates(items, spec.max_iterations);
  }
  if (const auto f = top.optional("tracking")) {
    spec.tracking = namesAxis(*f, {"closed", "open"}, "tracking mode");
  }
  if (const auto f = top.optional("timing")) {
    spec.timing = namesAxis(*f, supportedTimings(), "timing");
  }
  if (const auto f = top.optional("realism")) {
    spec.realism = namesAxis(*f, realismChoices(), "realism");
  }
  if (const auto f = top.optional("noise_seeds")) {
    spec.noise_seeds = seedsAxis(*f);
    const bool all_ideal = std::all_of(spec.realism.begin(), spec.realism.end(),
                                       [](const std::string& r) { return r == "ideal"; });
    if (all_ideal && spec.noise_seeds.size() > 1) {
      f->fail(
          "the ideal realism has no random draws, so several noise seeds would repeat "
          "identical episodes; give one seed or add a realism preset (lab, odometry)");
    }
  }
  if (const auto f = top.optional("start_offsets")) {
    spec.start_offsets = offsetsAxis(*f, spec.start_offset_lines);
  }
  if (const auto f = top.optional("goal_offsets")) {
    spec.goal_offsets = offsetsAxis(*f, spec.goal_offset_lines);
  }
  if (const auto f = top.optional("set")) readSet(*f, spec);
  if (const auto f = top.optional("samples")) readSamples(*f, spec);
  // realism. paths change the world's realism: section, which a preset of the realism: axis
  // replaces: those episodes would not have the values their columns say.
  for (const SetAxis& axis : spec.set) {
    if (axis.path.rfind("realism.", 0) != 0) continue;
    for (const std::string& r : spec.realism) {
      if (r != "world") {
        throw Error(source_name + ":" + std::to_string(axis.line) + ": set." + axis.path +
                    ": changes the world's realism: section, which realism: " + r +
                    " replaces; use realism: world and set realism.preset: " + r);
      }
    }
  }
  const auto drawn = std::find_if(spec.set.begin(), spec.set.end(),
                                  [](const SetAxis& a) { return a.distribution.has_value(); });
  if (drawn != spec.set.end() && !spec.samples) {
    throw Error(source_name + ":" + std::to_string(drawn->line) + ": set." + drawn->path +
                ": a distribution is drawn samples: times; add samples: {count: N, seed: S}");
  }
  if (drawn == spec.set.end() && spec.samples) {
    throw Error(source_name + ":" + std::to_string(spec.samples_line) +
                ": samples: draws the set: values that are distributions ({uniform: [a, b]}, "
                "{normal: [mean, sd]}, {choice: [...]}); this spec has none");
  }
  if (const auto f = top.optional("record")) readRecord(*f, spec.record);
  if (const auto f = top.optional("tolerance")) readTolerance(*f, spec.tolerance);

  const double count = static_cast<double>(spec.world_files.size()) * spec.planners.size() *
                       spec.controllers.size() * spec.steerings.size() * spec.smoothing.size() *
                       spec.seeds.size() * spec.max_iterations.size() * spec.tracking.size() *
                       spec.timing.size() * spec.realism.size() * spec.noise_seeds.size() *
                       spec.start_offsets.size() * spec.goal_offsets.size() * setCombinations(spec);
  if (count > static_cast<double>(kMaxEpisodes)) {
    root.fail("expands to " + std::to_string(static_cast<long long>(count)) +
              " episodes, more than the limit of " + std::to_string(kMaxEpisodes));
  }
  return spec;
}

SweepSpec loadSweepSpec(const std::string& path) {
  return parseSweepSpec(readInputFile(path, kMaxSpecBytes, "sweep spec"), path,
                        fs::path(path).parent_path().string());
}

}  // namespace parksim
