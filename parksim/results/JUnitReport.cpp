#include "parksim/results/JUnitReport.h"

#include <cmath>
#include <cstdio>

#include "parksim/core/AtomicFile.h"
#include "parksim/results/XmlText.h"

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
  int skipped = 0;
  double time_s = 0.0;

  void add(const JUnitCase& c) {
    ++tests;
    failures += c.failure ? 1 : 0;
    skipped += c.skipped && !c.failure ? 1 : 0;
    if (std::isfinite(c.time_s) && c.time_s > 0.0) time_s += c.time_s;
  }
};

// <testsuites> has no `skipped` attribute in the schema; <testsuite> has.
std::string countAttributes(const Counts& n, bool with_skipped) {
  std::string s = " tests=\"" + std::to_string(n.tests) + "\" failures=\"" +
                  std::to_string(n.failures) + "\" errors=\"0\"";
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
  if (c.properties.empty() && !c.failure && !c.skipped && c.system_out.empty()) {
    out += "/>\n";
    return;
  }
  out += ">\n";
  appendProperties(out, c.properties, "      ");
  if (c.failure) {
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
    for (const JUnitCase& c : s.cases) n += c.failure ? 1 : 0;
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

}  // namespace parksim
