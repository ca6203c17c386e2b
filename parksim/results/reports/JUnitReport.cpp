#include "parksim/results/reports/JUnitReport.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <tuple>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/results/reports/XmlText.h"
#include "parksim/results/tables/EpisodeRecord.h"

namespace parksim {

namespace {

std::string attr(const std::string& text) { return xmlEscaped(text, XmlContext::kAttribute); }

std::string content(const std::string& text) { return xmlEscaped(text, XmlContext::kContent); }

// Seconds with millisecond digits and no exponent: the schema's time pattern is digits, an
// optional point and more digits.
std::string seconds(double s) {
  if (!std::isfinite(s) || s < 0.0) s = 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", s);
  return buf;
}

struct Counts {
  int tests = 0;
  int failures = 0;
  int errors = 0;
  int skipped = 0;
  double time_s = 0.0;

  void add(const JUnitCase& c) {
    ++tests;
    errors += c.error ? 1 : 0;
    failures += c.failure && !c.error ? 1 : 0;
    skipped += c.skipped && !c.failure && !c.error ? 1 : 0;
    if (std::isfinite(c.time_s) && c.time_s > 0.0) time_s += c.time_s;
  }
};

// <testsuites> has no `skipped` attribute in the schema; <testsuite> has.
std::string countAttributes(const Counts& n, bool with_skipped) {
  std::string s = " tests=\"" + std::to_string(n.tests) + "\" failures=\"" +
                  std::to_string(n.failures) + "\" errors=\"" + std::to_string(n.errors) + "\"";
  if (with_skipped) s += " skipped=\"" + std::to_string(n.skipped) + "\"";
  return s + " time=\"" + seconds(n.time_s) + "\"";
}

void appendProperties(std::string& out, const std::vector<JUnitProperty>& properties,
                      const char* indent) {
  if (properties.empty()) return;
  out += indent;
  out += "<properties>\n";
  for (const JUnitProperty& p : properties) {
    out += indent;
    out += "  <property name=\"" + attr(p.name) + "\" value=\"" + attr(p.value) + "\"/>\n";
  }
  out += indent;
  out += "</properties>\n";
}

void appendCase(std::string& out, const JUnitCase& c) {
  out += "    <testcase name=\"" + attr(c.name) + "\" classname=\"" + attr(c.classname) +
         "\" time=\"" + seconds(c.time_s) + "\"";
  if (c.properties.empty() && !c.failure && !c.error && !c.skipped && c.system_out.empty()) {
    out += "/>\n";
    return;
  }
  out += ">\n";
  appendProperties(out, c.properties, "      ");
  if (c.error) {
    out += "      <error message=\"" + attr(c.error->message) + "\" type=\"" + attr(c.error->type) +
           "\">" + content(c.error->text) + "</error>\n";
  } else if (c.failure) {
    out += "      <failure message=\"" + attr(c.failure->message) + "\" type=\"" +
           attr(c.failure->type) + "\">" + content(c.failure->text) + "</failure>\n";
  } else if (c.skipped) {
    out += "      <skipped message=\"" + attr(*c.skipped) + "\"/>\n";
  }
  if (!c.system_out.empty()) {
    out += "      <system-out>" + content(c.system_out) + "</system-out>\n";
  }
  out += "    </testcase>\n";
}

}  // namespace

int junitFailures(const JUnitReport& report) {
  int n = 0;
  for (const JUnitSuite& s : report.suites) {
    for (const JUnitCase& c : s.cases) n += c.failure && !c.error ? 1 : 0;
  }
  return n;
}

int junitErrors(const JUnitReport& report) {
  int n = 0;
  for (const JUnitSuite& s : report.suites) {
    for (const JUnitCase& c : s.cases) n += c.error ? 1 : 0;
  }
  return n;
}

std::string junitXml(const JUnitReport& report) {
  Counts total;
  std::string suites;
  for (const JUnitSuite& s : report.suites) {
    Counts n;
    for (const JUnitCase& c : s.cases) {
      n.add(c);
      total.add(c);
    }
    suites += "  <testsuite name=\"" + attr(s.name) + "\"" + countAttributes(n, true) + ">\n";
    appendProperties(suites, s.properties, "    ");
    for (const JUnitCase& c : s.cases) appendCase(suites, c);
    suites += "  </testsuite>\n";
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"" + attr(report.name) +
         "\"" + countAttributes(total, false) + ">\n" + suites + "</testsuites>\n";
}

void writeJUnitFile(const std::string& path, const JUnitReport& report) {
  writeFileAtomically(path, junitXml(report));
}

namespace {

using Row = nlohmann::ordered_json;

std::string text(const Row& row, std::string_view key) {
  const auto it = row.find(key);
  if (it == row.end() || it->is_null()) return "";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

double numberOr(const Row& row, std::string_view key, double fallback) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number() ? it->get<double>() : fallback;
}

// Seeds are 64-bit: compared as integers, not as doubles.
std::uint64_t whole(const Row& row, std::string_view key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number_unsigned() ? it->get<std::uint64_t>() : 0;
}

// " start=dx,dy,dyaw" when the row's offset is not zero.
std::string offsetText(const Row& row, const std::string& what) {
  const std::string dx = text(row, what + "_dx_m");
  const std::string dy = text(row, what + "_dy_m");
  const std::string dyaw = text(row, what + "_dyaw_deg");
  const auto zero = [](const std::string& v) { return v.empty() || v == "0" || v == "0.0"; };
  if (zero(dx) && zero(dy) && zero(dyaw)) return "";
  return " " + what + "=" + dx + "," + dy + "," + dyaw;
}

std::string caseName(const Row& row) {
  std::string s = "seed=" + text(row, "seed") + " noise_seed=" + text(row, "noise_seed") +
                  offsetText(row, "start") + offsetText(row, "goal");
  if (row.contains("sample")) s += " sample=" + text(row, "sample");
  for (const auto& [key, value] : row.items()) {
    if (isSetKey(key)) s += " " + key + "=" + text(row, key);
  }
  if (row.contains("episode_id")) s += " id=" + text(row, "episode_id");
  return s;
}

// The numbers a reader of a failure wants next to its line.
std::string failureText(const Row& row) {
  std::string s = text(row, "failure");
  const auto mm = [&](const char* key) {
    const auto it = row.find(key);
    return it != row.end() && it->is_number() ? formatFixed(it->get<double>() * 1e3, 3) + " mm"
                                              : std::string("-");
  };
  if (row.contains("max_pos_err_m")) {
    s += "\nmax tracking error " + mm("max_pos_err_m") + ", goal error " + mm("goal_pos_err_m") +
         " / " + text(row, "goal_heading_err_deg") + " deg, " + text(row, "contacts") +
         " contact events";
  }
  return s;
}

JUnitCase recordCase(const Row& row, const std::string& suite) {
  JUnitCase c;
  c.name = caseName(row);
  c.classname = suite;
  c.time_s = numberOr(row, "episode_wall_s", numberOr(row, "sim_wall_s", 0.0));
  for (const EpisodeField& f : episodeFields()) {
    if (f.junit && row.contains(f.key))
      c.properties.push_back({std::string(f.key), text(row, f.key)});
  }
  for (const auto& [key, value] : row.items()) {
    if (isSetKey(key)) c.properties.push_back({key, text(row, key)});
  }
  const std::string status = text(row, "status");
  const auto met = row.find("met_tolerance");
  if (met != row.end() && met->is_boolean() && met->get<bool>()) return c;
  const std::string line = text(row, "failure");
  JUnitFailure why{line.empty() ? "did not meet its tolerance (" + status + ")" : line,
                   status.empty() ? "failed" : status, failureText(row)};
  // The user's code failed: the episode could not be judged (an error, not a failure).
  if (status == "planner_error" || status == "controller_error") {
    c.error = std::move(why);
  } else {
    c.failure = std::move(why);
  }
  return c;
}

}  // namespace

JUnitReport episodesJUnit(const std::vector<Row>& records, const std::string& name,
                          const RecordSuite& suite_of) {
  std::map<std::string, std::vector<const Row*>> suites;
  for (const Row& row : records) suites[suite_of(row)].push_back(&row);
  JUnitReport report{name, {}};
  for (auto& [suite_name, members] : suites) {
    const auto key_of = [](const Row* r) {
      return std::make_tuple(whole(*r, "seed"), whole(*r, "noise_seed"), whole(*r, "sample"),
                             text(*r, "episode_id"));
    };
    std::stable_sort(members.begin(), members.end(),
                     [&](const Row* a, const Row* b) { return key_of(a) < key_of(b); });
    JUnitSuite suite;
    suite.name = suite_name;
    for (const Row* row : members) suite.cases.push_back(recordCase(*row, suite.name));
    report.suites.push_back(std::move(suite));
  }
  return report;
}

}  // namespace parksim
