#include "parksim/scenario/yaml/YamlField.h"

#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <sstream>
#include <system_error>
#include <unordered_map>
#include <utility>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"

namespace parksim {

namespace {

// yaml-cpp gives plain scalars the non-specific tag "?" and quoted or block scalars "!".
// Only plain scalars are numbers or booleans: `"0.5"` is a string in YAML.
bool isPlainScalar(const YAML::Node& node) { return node.IsScalar() && node.Tag() == "?"; }

// What the node is, for "got ..." in messages.
std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null: return "null";
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list of " + std::to_string(node.size());
    case YAML::NodeType::Scalar:
      return isPlainScalar(node) ? node.Scalar() : "the string \"" + node.Scalar() + "\"";
    case YAML::NodeType::Undefined: break;
  }
  return "nothing";
}

// std::from_chars over the whole text; YAML also allows a leading '+', from_chars does not.
template <typename T>
bool parseWhole(const std::string& text, T& out) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') {
    ++first;
    if (first != last && (*first == '+' || *first == '-')) return false;
  }
  const auto [end, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && end == last;
}

// Out of double's range: from_chars refuses; a too large magnitude is an infinity (so that
// 1e309 and .inf say the same), a too small one rounds to zero.
bool parseOutOfRange(const std::string& text, double& out) {
  std::string_view body = text;
  bool negative = false;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  double probe = 0.0;
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), probe);
  if (ec != std::errc::result_out_of_range || end != body.data() + body.size()) return false;
  const std::size_t e = body.find_first_of("eE");
  const bool tiny = e != std::string_view::npos && e + 1 < body.size() && body[e + 1] == '-';
  out = tiny ? 0.0 : HUGE_VAL;
  if (negative) out = -out;
  return true;
}

// YAML 1.2 spells infinities and NaN as .inf / -.inf / .nan (any case of the letters);
// from_chars spells them inf / nan. Both parse here so that they can be reported as
// non-finite instead of as not-a-number.
bool parseYamlDouble(const std::string& text, double& out) {
  std::string_view body = text;
  bool negative = false;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  if (body == ".inf" || body == ".Inf" || body == ".INF") {
    out = negative ? -HUGE_VAL : HUGE_VAL;
    return true;
  }
  if (text == ".nan" || text == ".NaN" || text == ".NAN") {
    out = std::nan("");
    return true;
  }
  return parseWhole(text, out) || parseOutOfRange(text, out);
}

std::string joinKeys(std::initializer_list<std::string_view> keys) {
  std::string out;
  for (const std::string_view key : keys) {
    if (!out.empty()) out += ", ";
    out += key;
  }
  return out;
}

}  // namespace

int lineOf(const YAML::Mark& mark) { return mark.is_null() ? 1 : mark.line + 1; }

std::string formatNumber(double value) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

YamlField::YamlField(YAML::Node node, std::string path, int line, std::string_view source)
    : node_(std::move(node)), path_(std::move(path)), line_(line), source_(source) {}

std::string YamlField::describeValue() const { return describe(node_); }

void YamlField::fail(std::string_view what) const {
  // The document itself has no key; name it so the message keeps its "where: what" shape.
  const std::string where = path_.empty() ? "(document)" : path_;
  // Without a source (a pose from the command line) there is no line either.
  std::string at;
  if (!source_.empty()) at = std::string(source_) + ":" + std::to_string(line_) + ": ";
  throw Error(escapeText(at + where + ": " + std::string(what)));
}

YamlField YamlField::child(YAML::Node node, std::string path, const YAML::Node& line_from) const {
  // yaml-cpp marks an empty value at the start of the next line; the parent's line is closer.
  const YAML::Mark mark = line_from.Mark();
  const int line = (line_from.IsNull() || mark.is_null()) ? line_ : lineOf(mark);
  return YamlField(std::move(node), std::move(path), line, source_);
}

double YamlField::number() const {
  double value = 0.0;
  if (!isPlainScalar(node_) || !parseYamlDouble(node_.Scalar(), value)) {
    fail("must be a number, got " + describe(node_));
  }
  if (!std::isfinite(value)) fail("must be a finite number, got " + node_.Scalar());
  return value;
}

double YamlField::inRange(double lo, double hi, std::string_view unit) const {
  const double value = number();
  if (!(value >= lo && value <= hi)) {
    fail("must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "]" + std::string(unit) +
         ", got " + node_.Scalar());
  }
  return value;
}

double YamlField::positive() const {
  const double value = number();
  if (!(value > 0.0)) fail("must be positive, got " + node_.Scalar());
  return value;
}

double YamlField::nonNegative() const {
  const double value = number();
  if (!(value >= 0.0)) fail("must be zero or positive, got " + node_.Scalar());
  return value;
}

int YamlField::positiveInt() const {
  int value = 0;
  if (!isPlainScalar(node_) || !parseWhole(node_.Scalar(), value)) {
    fail("must be an integer, got " + describe(node_));
  }
  if (value <= 0) fail("must be positive, got " + node_.Scalar());
  return value;
}

bool YamlField::boolean() const {
  if (isPlainScalar(node_)) {
    const std::string& s = node_.Scalar();
    if (s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "false" || s == "False" || s == "FALSE") return false;
  }
  fail("must be true or false, got " + describe(node_));
}

std::string YamlField::text() const {
  if (!node_.IsScalar()) fail("must be a string, got " + describe(node_));
  if (node_.Scalar().empty()) fail("must not be empty");
  return node_.Scalar();
}

std::string YamlField::name() const {
  std::string value = text();
  if (!isPrintableUtf8(value)) {
    fail("must be UTF-8 text without control characters, got \"" + value + "\"");
  }
  return value;
}

std::vector<double> YamlField::numbers(std::size_t n, std::string_view shape) const {
  if (!node_.IsSequence() || node_.size() != n) {
    fail("must be a list " + std::string(shape) + " of " + std::to_string(n) + " numbers, got " +
         describe(node_));
  }
  std::vector<double> out;
  out.reserve(n);
  for (const YamlField& item : items()) out.push_back(item.number());
  return out;
}

std::vector<YamlField> YamlField::items() const {
  if (!node_.IsSequence()) fail("must be a list, got " + describe(node_));
  std::vector<YamlField> out;
  out.reserve(node_.size());
  for (std::size_t i = 0; i < node_.size(); ++i) {
    const YAML::Node item = node_[i];
    out.push_back(child(item, path_ + "[" + std::to_string(i) + "]", item));
  }
  return out;
}

std::vector<YamlField> YamlField::listUpTo(std::size_t max_items) const {
  if (node_.IsNull()) return {};
  if (node_.IsSequence() && node_.size() > max_items) {
    fail("holds " + std::to_string(node_.size()) + " items; at most " + std::to_string(max_items) +
         " are allowed");
  }
  return items();
}

YamlMap YamlField::map(std::initializer_list<std::string_view> allowed) const {
  YamlMap m(*this);
  m.rejectUnknownKeys(allowed);
  return m;
}

namespace {

bool isMergeKey(const YAML::Node& key) { return isPlainScalar(key) && key.Scalar() == "<<"; }

}  // namespace

YamlMap::YamlMap(const YamlField& field) : field_(field) {
  const YAML::Node& node = field_.node();
  if (!node.IsMap()) field_.fail("must be a map, got " + describe(node));
  // Merged maps add what the map does not have; the first merged map wins over later ones,
  // and a merged map's own merges come right after its own keys. That order is a depth-first
  // walk, done with an explicit stack and each map visited once: a map merged a second time
  // (by a fan-out of aliases, or by a cycle back to itself) adds nothing, so skipping it keeps
  // the meaning while work and stack depth stay bounded (a "billion laughs" of merge keys).
  // Small linear sets: a map has a dozen keys, and worlds are read per sweep episode.
  std::vector<const std::string*> seen;
  std::vector<YamlField> pending{field_};
  // Identity of a node: its position in the text, then YAML::Node::is among the few that
  // share a position (nodes of override values parsed from other text).
  std::vector<std::pair<std::size_t, YAML::Node>> visited;
  std::size_t work = 0;
  const auto count = [&work](const YamlField& at, std::size_t items) {
    work += items;
    if (work > kMaxMergedItems) {
      at.fail("merge keys bring in more than " + std::to_string(kMaxMergedItems) +
              " maps and keys (the limit for one map)");
    }
  };
  const auto contains = [](const std::vector<const std::string*>& names, const std::string& s) {
    return std::any_of(names.begin(), names.end(), [&s](const std::string* n) { return *n == s; });
  };
  while (!pending.empty()) {
    const YamlField source = pending.back();
    pending.pop_back();
    if (!source.node().IsMap()) source.fail("a merge key takes a map or a list of maps");
    const auto pos = static_cast<std::size_t>(source.node().Mark().pos);
    const bool again = std::any_of(visited.begin(), visited.end(), [&](const auto& v) {
      return v.first == pos && v.second.is(source.node());
    });
    if (again) continue;
    visited.emplace_back(pos, source.node());
    std::vector<const std::string*> keys_here;
    std::vector<YamlField> merges_here;
    for (const auto& entry : source.node()) {
      count(source, 1);
      const YAML::Node& key = entry.first;
      // The field of this entry, for messages and merges only (a path per key costs).
      const auto at = [&] {
        const std::string key_path =
            field_.path().empty() ? key.Scalar() : field_.path() + "." + key.Scalar();
        return source.child(key, key_path, key);
      };
      if (!key.IsScalar() || key.Scalar().empty()) at().fail("keys must be names");
      if (contains(keys_here, key.Scalar())) at().fail("duplicate key");
      keys_here.push_back(&key.Scalar());
      if (isMergeKey(key)) {
        const YamlField value = source.child(entry.second, at().path(), key);
        // Counted before a long list of aliases is built.
        count(value, entry.second.IsSequence() ? entry.second.size() : 1);
        if (entry.second.IsSequence()) {
          for (const YamlField& item : value.items()) merges_here.push_back(item);
        } else {
          merges_here.push_back(value);
        }
        continue;
      }
      if (!contains(seen, key.Scalar())) {
        seen.push_back(&key.Scalar());
        entries_.emplace_back(key, entry.second);
      }
    }
    pending.insert(pending.end(), merges_here.rbegin(), merges_here.rend());
  }
}

namespace {

// Counts documents without building them. yaml-cpp 0.7 reports an endless run of empty
// documents for a stray flow indicator such as a lone `,` (upstream issue 1040): every
// document then starts where the previous one did. That is the parser stuck, and the file a
// syntax error there.
struct DocumentCounter final : YAML::EventHandler {
  YAML::Mark start;    // where the last document started
  YAML::Mark content;  // where its first node is
  bool seen = false;
  void node(const YAML::Mark& mark) {
    if (!seen) content = mark;
    seen = true;
  }
  void OnDocumentStart(const YAML::Mark& mark) override {
    start = mark;
    seen = false;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string&) override {
    node(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnMapEnd() override {}
};

[[noreturn]] void syntaxError(const std::string& source_name, int line, const std::string& what) {
  throw Error(escapeText(source_name + ":" + std::to_string(line) + ": (syntax): " + what));
}

}  // namespace

YAML::Node loadSingleYamlDocument(const std::string& text, const std::string& source_name,
                                  std::string_view kind, std::string_view format) {
  int documents = 0;
  YAML::Mark second;
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    DocumentCounter counter;
    int last_start = -1;
    while (parser.HandleNextDocument(counter)) {
      if (counter.start.pos <= last_start) {
        const auto pos = static_cast<std::size_t>(std::max(counter.start.pos, 0));
        const std::string what =
            pos < text.size() ? "unexpected '" + text.substr(pos, 1) + "'" : "unexpected input";
        syntaxError(source_name, lineOf(counter.start),
                    what + " (outside any [ ] or { } list or map)");
      }
      last_start = counter.start.pos;
      if (++documents == 2) second = counter.content;
    }
  } catch (const YAML::Exception& e) {
    syntaxError(source_name, lineOf(e.mark), e.msg);
  }
  if (documents == 0) {
    YamlField(YAML::Node(), "", 1, source_name)
        .fail("empty; a " + std::string(kind) +
              " is a map that starts with format: " + std::string(format));
  }
  if (documents > 1) {
    YamlField(YAML::Node(), "", lineOf(second), source_name)
        .fail("a " + std::string(kind) + " holds one YAML document, found " +
              std::to_string(documents));
  }
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    syntaxError(source_name, lineOf(e.mark), e.msg);
  }
}

std::vector<std::string> YamlMap::keys() const {
  std::vector<std::string> out;
  for (const auto& entry : entries_) out.push_back(entry.first.Scalar());
  return out;
}

void YamlMap::rejectUnknownKeys(std::initializer_list<std::string_view> allowed) const {
  for (const auto& entry : entries_) {
    const std::string& key = entry.first.Scalar();
    bool known = false;
    for (const std::string_view a : allowed) known = known || a == key;
    if (!known) {
      const std::string key_path = field_.path().empty() ? key : field_.path() + "." + key;
      field_.child(entry.first, key_path, entry.first)
          .fail("unknown field; expected one of: " + joinKeys(allowed));
    }
  }
}

std::optional<YamlField> YamlMap::optional(std::string_view key) const {
  for (const auto& entry : entries_) {
    if (entry.first.Scalar() == key) {
      const std::string key_path =
          field_.path().empty() ? std::string(key) : field_.path() + "." + std::string(key);
      // The key's line: a block map or list value starts on the line after its key.
      return field_.child(entry.second, key_path, entry.first);
    }
  }
  return std::nullopt;
}

YamlField YamlMap::required(std::string_view key) const {
  std::optional<YamlField> value = optional(key);
  if (!value) {
    const std::string key_path =
        field_.path().empty() ? std::string(key) : field_.path() + "." + std::string(key);
    YamlField(field_.node(), key_path, field_.line(), field_.source_)
        .fail("missing required field");
  }
  return *value;
}

}  // namespace parksim
