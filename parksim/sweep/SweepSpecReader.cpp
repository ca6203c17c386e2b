#include "parksim/sweep/SweepSpecReader.h"

#include <glob.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "parksim/core/Error.h"
#include "parksim/core/InputFile.h"
#include "parksim/planner/PlanScenario.h"
#include "parksim/planner/TreePlanner.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/scenario/YamlField.h"
#include "parksim/sim/ExecutionDef.h"
#include "parksim/sweep/EpisodeSetup.h"

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

// `set:` axes: each world field's values; every combination is a variant of every world.
void readSetAxes(const YamlField& field, SweepSpec& spec) {
  const YamlMap m(field);
  std::vector<std::vector<ScenarioOverride>> combinations{{}};
  for (const std::string& path : m.keys()) {
    const YamlField values = *m.optional(path);
    std::vector<std::string> texts;
    for (const YamlField& item : axisItems(values)) {
      YAML::Emitter out;
      out.SetSeqFormat(YAML::Flow);
      out.SetMapFormat(YAML::Flow);
      out << item.node();
      texts.emplace_back(out.c_str());
      if (std::count(texts.begin(), texts.end(), texts.back()) > 1) {
        item.fail("repeats the value " + texts.back());
      }
    }
    spec.set_axes.emplace_back(path, texts);
    std::vector<std::vector<ScenarioOverride>> grown;
    for (const auto& base : combinations) {
      for (const std::string& v : texts) {
        auto next = base;
        next.push_back(
            {path, v,
             spec.source_path + ":" + std::to_string(values.line()) + ": set " + path + "=" + v});
        grown.push_back(std::move(next));
      }
    }
    combinations = std::move(grown);
  }
  std::vector<std::string> files;
  std::vector<std::string> paths;
  for (std::size_t w = 0; w < spec.world_paths.size(); ++w) {
    for (const auto& overrides : combinations) {
      files.push_back(spec.world_files[w]);
      paths.push_back(spec.world_paths[w]);
      spec.world_overrides.push_back(overrides);
    }
  }
  spec.world_files = std::move(files);
  spec.world_paths = std::move(paths);
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
  top.rejectUnknownKeys({"format", "name", "worlds", "planners", "steering", "smoothing", "seeds",
                         "max_iterations", "tracking", "timing", "realism", "noise_seeds",
                         "start_offsets", "goal_offsets", "record", "tolerance", "set"});

  SweepSpec spec;
  spec.source_path = source_name;
  // name(): UTF-8 without control characters; it reaches the terminal, reports and job names.
  spec.name = top.required("name").name();
  readWorlds(top.required("worlds"), base_dir, spec);
  spec.world_overrides.assign(spec.world_paths.size(), {});
  if (const auto f = top.optional("set")) {
    spec.world_overrides.clear();
    readSetAxes(*f, spec);
  }

  const std::vector<std::string> planner_names = builtInPlanners().names();
  std::vector<std::string> steering_names;
  for (SteeringKind k : allSteeringKinds()) steering_names.emplace_back(toString(k));
  if (const auto f = top.optional("planners")) {
    spec.planners = namesAxis(*f, planner_names, "planner");
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
  if (const auto f = top.optional("record")) readRecord(*f, spec.record);
  if (const auto f = top.optional("tolerance")) readTolerance(*f, spec.tolerance);

  const double count = static_cast<double>(spec.world_files.size()) * spec.planners.size() *
                       spec.steerings.size() * spec.smoothing.size() * spec.seeds.size() *
                       spec.max_iterations.size() * spec.tracking.size() * spec.timing.size() *
                       spec.realism.size() * spec.noise_seeds.size() * spec.start_offsets.size() *
                       spec.goal_offsets.size();
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
