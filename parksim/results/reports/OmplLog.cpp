#include "parksim/results/reports/OmplLog.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>

#include <ompl/base/PlannerStatus.h>

#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/system/Provenance.h"
#include "parksim/planner/steering/OmplPlugin.h"

namespace parksim::bench {
namespace {

namespace ob = ompl::base;

std::string number(double v) {
  if (std::isnan(v)) return "";
  return formatGeneral(v, 9);
}

std::string count(long v) { return v < 0 ? "" : std::to_string(v); }

struct Planner {
  std::string library, planner, space, budget;
  std::vector<const BenchRecord*> runs;
};

// One line per experiment field: the format has no quoting, so newlines inside a one-line
// value would break the parser.
std::string oneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

// A multi-line value between "<<<|" and "|>>>" lines. (Here and below, one-character pieces are
// appended on their own: GCC 12 warns falsely (-Wrestrict) about `"x" + std::string` at -O2.)
void block(std::string& out, const std::string& text) {
  out += "<<<|\n";
  out += text;
  if (!text.empty() && text.back() != '\n') out += '\n';
  out += "|>>>\n";
}

// OMPL's names of its planner statuses, by code: loaded once per log (they need libompl, so
// the plugin).
std::vector<std::string> omplStatusNames() {
  const OmplPlugin ompl;
  std::vector<std::string> names;
  for (int i = 0; const char* name = ompl.api().status_name(i); ++i) names.emplace_back(name);
  return names;
}

int statusCode(const BenchRecord& r, const std::vector<std::string>& status_names) {
  if (r.solved) return ob::PlannerStatus::EXACT_SOLUTION;
  for (std::size_t i = 0; i < status_names.size(); ++i) {
    if (r.status == status_names[i]) return static_cast<int>(i);
  }
  if (r.status == "iteration_limit" || r.status == "time_limit") {
    return ob::PlannerStatus::TIMEOUT;
  }
  if (r.status == "invalid_start") return ob::PlannerStatus::INVALID_START;
  if (r.status == "invalid_goal") return ob::PlannerStatus::INVALID_GOAL;
  if (r.status.rfind("child", 0) == 0) return ob::PlannerStatus::CRASH;
  return ob::PlannerStatus::UNKNOWN;
}

}  // namespace

int omplStatusCode(const BenchRecord& r) { return statusCode(r, omplStatusNames()); }

std::string omplLogTimeNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", &tm);
  return buf;
}

std::string omplBenchmarkLog(const OmplLogInfo& info, const std::vector<BenchRecord>& records) {
  std::vector<Planner> planners;
  for (const BenchRecord& r : records) {
    auto it = std::find_if(planners.begin(), planners.end(), [&](const Planner& p) {
      return p.library == r.library && p.planner == r.planner && p.space == r.space &&
             p.budget == r.budget;
    });
    if (it == planners.end()) {
      planners.push_back({r.library, r.planner, r.space, r.budget, {}});
      it = std::prev(planners.end());
    }
    it->runs.push_back(&r);
  }
  std::map<std::string, int> budgets_per_name;
  auto baseName = [](const Planner& p) { return p.library + "_" + p.planner + "_" + p.space; };
  for (const Planner& p : planners) ++budgets_per_name[baseName(p)];

  std::string out;
  out += "parksim version " + buildProvenance().version + "\n";
  out += "Experiment " + oneLine(info.experiment.empty() ? "NO_NAME" : info.experiment) + "\n";
  out += "0 experiment properties\n";
  out += "Running on " + oneLine(info.host.empty() ? "UNKNOWN" : info.host) + "\n";
  out += "Starting at " + oneLine(info.start_time) + "\n";
  block(out, info.setup);
  block(out, info.cpu_info);
  // Each run carries its own seed (property "seed"); there is no single experiment seed.
  out += "0 is the random seed\n";
  out += number(info.time_limit_s) + " seconds per run\n";
  out += "0 MB per run\n";
  out += std::to_string(info.runs_per_planner) + " runs per planner\n";
  out += number(info.total_s) + " seconds spent to collect the data\n";
  out += "1 enum type\nstatus";
  const std::vector<std::string> status_names = omplStatusNames();
  for (const std::string& name : status_names) {
    out += '|';
    out += name;
  }
  out += '\n';
  out += std::to_string(planners.size()) + " planners\n";

  // Sorted by name, as OMPL writes them.
  const std::vector<std::string> properties = {"cusps INTEGER",        "first solution time REAL",
                                               "graph states INTEGER", "iterations INTEGER",
                                               "seed INTEGER",         "solution clearance REAL",
                                               "solution length REAL", "solved BOOLEAN",
                                               "status ENUM",          "time REAL",
                                               "valid BOOLEAN"};
  for (const Planner& p : planners) {
    std::string name = baseName(p);
    if (budgets_per_name[name] > 1) {
      name += '_';
      name += p.budget;
    }
    out += oneLine(name) + "\n";
    out += "3 common properties\n";
    out += "budget = " + oneLine(p.budget) + "\n";
    out += "library = " + oneLine(p.library) + "\n";
    out += "space = " + oneLine(p.space) + "\n";
    out += std::to_string(properties.size()) + " properties for each run\n";
    for (const std::string& prop : properties) out += prop + "\n";
    out += std::to_string(p.runs.size()) + " runs\n";
    for (const BenchRecord* r : p.runs) {
      const std::vector<std::string> values = {count(r->cusps),
                                               number(r->time_first_s),
                                               count(r->tree_size),
                                               count(r->iterations),
                                               std::to_string(r->seed),
                                               number(r->min_clearance_m),
                                               number(r->length_m),
                                               r->solved ? "1" : "0",
                                               std::to_string(statusCode(*r, status_names)),
                                               number(r->time_total_s),
                                               r->valid ? "1" : "0"};
      for (const std::string& v : values) out += v + "; ";
      out += "\n";
    }
    // Progress properties, when recorded: values of one sample separated by ',' and samples by
    // ';'. OMPL writes a sample's values in the alphabetical order of the property names (a
    // std::map); the names are listed in that order too, so both readings agree.
    const bool any_progress = std::any_of(
        p.runs.begin(), p.runs.end(), [](const BenchRecord* r) { return !r->progress.empty(); });
    if (any_progress) {
      out += "2 progress properties for each run\nbest cost REAL\ntime REAL\n";
      out += std::to_string(p.runs.size()) + " runs\n";
      for (const BenchRecord* r : p.runs) {
        for (const auto& [t, cost] : r->progress) {
          out += number(cost);
          out += ',';
          out += number(t);
          out += ",;";
        }
        out += '\n';
      }
    }
    out += ".\n";
  }
  return out;
}

}  // namespace parksim::bench
