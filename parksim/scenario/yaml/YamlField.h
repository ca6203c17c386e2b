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
#include <utility>
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
  std::string_view source() const { return source_; }

  /// What the value is, for "got ..." in messages: "null", "a map", "a list of 2", the scalar.
  std::string describeValue() const;

  /// Throws Error at this field's line and path. Control characters and bytes that are not
  /// UTF-8 (from the file) are escaped. Line 0 leaves out the line, an empty source the file.
  [[noreturn]] void fail(std::string_view what) const;

  /// A plain (unquoted) scalar that parses completely as a finite number.
  double number() const;
  /// number(), and > 0.
  double positive() const;
  /// number(), and >= 0.
  double nonNegative() const;
  /// number(), and lo <= value <= hi ("must be in [lo, hi]" otherwise; `unit` is appended to
  /// the bounds in the message, e.g. " degrees").
  double inRange(double lo, double hi, std::string_view unit = "") const;
  /// A plain scalar that parses completely as an int, and > 0.
  int positiveInt() const;
  /// A plain scalar: true or false (YAML 1.2 spellings only, so `yes`/`no` are rejected).
  bool boolean() const;
  /// A non-empty scalar, quoted or not.
  std::string text() const;
  /// text() that is valid UTF-8 without control characters: names end up in JSON files,
  /// CSV files and on the terminal.
  std::string name() const;
  /// A list of exactly `n` finite numbers; `shape` names its items for messages, e.g.
  /// "[x, y, yaw_deg]".
  std::vector<double> numbers(std::size_t n, std::string_view shape) const;
  /// A list of any length (possibly empty); each item carries its own line.
  std::vector<YamlField> items() const;
  /// items(), also accepting an empty value (`key:` with nothing) as an empty list, and at
  /// most `max_items` of them ("at most N items (the limit for ...)" otherwise).
  std::vector<YamlField> listUpTo(std::size_t max_items) const;
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

/// Most maps and keys one map may bring in through merge keys, its own keys included (each
/// merged map counts once, however often it is merged). A real map has a dozen keys; the
/// limit bounds the work of a file built to explode (docs/world-format.md).
inline constexpr std::size_t kMaxMergedItems = 256;

/// A map node. Construction rejects anything that is not a map and maps with repeated keys
/// (yaml-cpp would otherwise keep the first and silently ignore the rest). YAML merge keys
/// (`<<: *anchor` or `<<: [*a, *b]`) are resolved here, as YAML 1.1 defines them: the merged
/// maps' entries are added unless the map has the key itself (earlier merged maps win). A map
/// merged twice (or merging itself through a cycle) adds nothing the second time.
class YamlMap {
 public:
  explicit YamlMap(const YamlField& field);

  /// The map's own and merged keys, in order (own keys first).
  std::vector<std::string> keys() const;

  /// Throws on the first key not in `allowed`, listing the allowed ones.
  void rejectUnknownKeys(std::initializer_list<std::string_view> allowed) const;
  /// The value under `key`, or nothing when absent.
  std::optional<YamlField> optional(std::string_view key) const;
  /// The value under `key`; throws at the map's line when absent.
  YamlField required(std::string_view key) const;

 private:
  YamlField field_;
  std::vector<std::pair<YAML::Node, YAML::Node>> entries_;  // key, value; merges resolved
};

/// The one YAML document of `text`, or Error "<source>:<line>: (syntax): ..." /
/// "(document): ...". Terminates on every input: yaml-cpp 0.7 reads an endless run of empty
/// documents from a stray `,` (its issue 1040), so a first pass counts documents and stops
/// when the parser makes no progress; `kind` ("world file") and `format` ("parksim-world/1")
/// word the messages for an empty text and for several documents.
YAML::Node loadSingleYamlDocument(const std::string& text, const std::string& source_name,
                                  std::string_view kind, std::string_view format);

/// Shortest text that reads back as the same double ("0.1", "1e-05").
std::string formatNumber(double value);

/// 1-based line of a yaml-cpp mark; 1 when yaml-cpp did not record a position.
int lineOf(const YAML::Mark& mark);

}  // namespace parksim
