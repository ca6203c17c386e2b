#include "parksim/scenario/YamlField.h"

#include <charconv>
#include <cmath>
#include <set>
#include <system_error>
#include <utility>

#include "parksim/core/Error.h"

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
  return parseWhole(text, out);
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

void YamlField::fail(std::string_view what) const {
  // The document itself has no key; name it so the message keeps its "where: what" shape.
  const std::string where = path_.empty() ? "(document)" : path_;
  throw Error(std::string(source_) + ":" + std::to_string(line_) + ": " + where + ": " +
              std::string(what));
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

YamlMap YamlField::map(std::initializer_list<std::string_view> allowed) const {
  YamlMap m(*this);
  m.rejectUnknownKeys(allowed);
  return m;
}

YamlMap::YamlMap(const YamlField& field) : field_(field) {
  const YAML::Node& node = field_.node();
  if (!node.IsMap()) field_.fail("must be a map, got " + describe(node));
  std::set<std::string> seen;
  for (const auto& entry : node) {
    const YAML::Node& key = entry.first;
    const std::string key_path =
        field_.path().empty() ? key.Scalar() : field_.path() + "." + key.Scalar();
    const YamlField at = field_.child(key, key_path, key);
    if (!key.IsScalar() || key.Scalar().empty()) at.fail("keys must be names");
    if (!seen.insert(key.Scalar()).second) at.fail("duplicate key");
  }
}

void YamlMap::rejectUnknownKeys(std::initializer_list<std::string_view> allowed) const {
  for (const auto& entry : field_.node()) {
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
  for (const auto& entry : field_.node()) {
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
