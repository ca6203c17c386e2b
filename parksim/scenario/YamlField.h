#pragma once
// Typed, located access to a parsed YAML document. Every accessor checks the node's type and
// value and throws Error("file:line: path: what is wrong"), so a reader built on it names
// exactly which entry of which file is bad. Internal to the scenario module: its header pulls
// in yaml-cpp, which the module's public API does not expose.

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace parksim {

class YamlMap;

/// One node of a document together with its field path ("obstacles[2].size") and the 1-based
/// line it was written on. Holds a view of the source name: the caller keeps it alive.
class YamlField {
 public:
  YamlField(YAML::Node node, std::string path, int line, std::string_view source);

  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  int line() const { return line_; }

  /// Throws Error at this field's line and path.
  [[noreturn]] void fail(std::string_view what) const;

  /// A plain (unquoted) scalar that parses completely as a finite number.
  double number() const;
  /// number(), and > 0.
  double positive() const;
  /// number(), and >= 0.
  double nonNegative() const;
  /// A plain scalar that parses completely as an int, and > 0.
  int positiveInt() const;
  /// A plain scalar: true or false (YAML 1.2 spellings only, so `yes`/`no` are rejected).
  bool boolean() const;
  /// A non-empty scalar, quoted or not.
  std::string text() const;
  /// A list of exactly `n` finite numbers; `shape` names its items for messages, e.g.
  /// "[x, y, yaw_deg]".
  std::vector<double> numbers(std::size_t n, std::string_view shape) const;
  /// A list of any length (possibly empty); each item carries its own line.
  std::vector<YamlField> items() const;
  /// A map whose keys are all in `allowed`, without duplicates.
  YamlMap map(std::initializer_list<std::string_view> allowed) const;

 private:
  friend class YamlMap;
  YamlField child(YAML::Node node, std::string path, const YAML::Node& line_from) const;

  YAML::Node node_;
  std::string path_;
  int line_;
  std::string_view source_;
};

/// A map node. Construction rejects anything that is not a map and maps with repeated keys
/// (yaml-cpp would otherwise keep the first and silently ignore the rest).
class YamlMap {
 public:
  explicit YamlMap(const YamlField& field);

  /// Throws on the first key not in `allowed`, listing the allowed ones.
  void rejectUnknownKeys(std::initializer_list<std::string_view> allowed) const;
  /// The value under `key`, or nothing when absent.
  std::optional<YamlField> optional(std::string_view key) const;
  /// The value under `key`; throws at the map's line when absent.
  YamlField required(std::string_view key) const;

 private:
  YamlField field_;
};

/// Shortest text that reads back as the same double ("0.1", "1e-05").
std::string formatNumber(double value);

/// 1-based line of a yaml-cpp mark; 1 when yaml-cpp did not record a position.
int lineOf(const YAML::Mark& mark);

}  // namespace parksim
