// `example`: a small planner as a user would write one against the plugin API. A* over a grid
// of positions covering the lot; two cells are joined by the problem's steering function from
// rest to rest (turn, drive, turn with the default balkcom-mason steering), each join checked
// by the problem's motion validator, and every expanded cell tries to reach the goal the same
// way. The path found is smoothed and timed exactly as parksim's own planners' are
// (finishPlan). Being a plugin's, its plan is checked again before it is driven.

#include <cmath>
#include <queue>
#include <vector>

#include "ExamplePlugins.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/base/PlanFinishing.h"

namespace example {

namespace {

struct GridDef {
  double cell_m = 0.0;  ///< grid cell, m; 0: half the footprint's radius
};

class GridPlanner : public parksim::Planner {
 public:
  explicit GridPlanner(const GridDef& def) : def_(def) {}

  parksim::PlanResult solve(const parksim::PlanningProblem& p) override {
    using namespace parksim;
    const Scenario& s = p.scenario;
    const LotBounds& lot = s.lot;
    const double cell = def_.cell_m > 0.0 ? def_.cell_m : 0.5 * footprintRadius(s.robot);
    const long nx = static_cast<long>(std::ceil((lot.x_max_m - lot.x_min_m) / cell));
    const long ny = static_cast<long>(std::ceil((lot.y_max_m - lot.y_min_m) / cell));
    PlanResult result;
    if (nx * ny > 4'000'000) {
      result.message = "the lot has more than 4 million cells of " + std::to_string(cell) + " m";
      return result;
    }
    // Node 0 is the start; node 1 + i + nx j is cell (i, j).
    std::vector<Node> nodes(static_cast<std::size_t>(1 + nx * ny));
    nodes[0] = {s.start, 0.0, -1, {}, false};
    using Entry = std::pair<double, long>;  // f, node
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    const Pose2 goal = s.goal.pose;
    open.push({positionDistance(s.start, goal), 0});
    int expansions = 0;
    const SearchDef& search = p.search();
    while (!open.empty() && expansions < search.max_iterations && !search.cancelled()) {
      const long n = open.top().second;
      open.pop();
      if (nodes[n].closed_) continue;
      nodes[n].closed_ = true;
      ++expansions;
      if (p.progress) p.progress(expansions, search.max_iterations);
      // The goal from here?
      if (Trajectory to_goal; join(p, nodes[n].pose, goal, to_goal)) {
        result.trajectory = pathTo(nodes, n);
        result.trajectory.append(to_goal);
        break;
      }
      const long ci = n == 0 ? cellOf(s.start.x, lot.x_min_m, cell, nx) : (n - 1) % nx;
      const long cj = n == 0 ? cellOf(s.start.y, lot.y_min_m, cell, ny) : (n - 1) / nx;
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const long i = ci + di;
          const long j = cj + dj;
          if ((di == 0 && dj == 0) || i < 0 || j < 0 || i >= nx || j >= ny) continue;
          const long m = 1 + i + nx * j;
          if (nodes[m].closed_) continue;
          const Pose2& from = nodes[n].pose;
          const double x = lot.x_min_m + (static_cast<double>(i) + 0.5) * cell;
          const double y = lot.y_min_m + (static_cast<double>(j) + 0.5) * cell;
          const Pose2 to{x, y, std::atan2(y - from.y, x - from.x)};
          const double g = nodes[n].cost + positionDistance(from, to);
          if (nodes[m].parent >= 0 && nodes[m].cost <= g) continue;
          Trajectory edge;
          if (!join(p, from, to, edge)) continue;
          nodes[m] = {to, g, n, std::move(edge), false};
          open.push({g + positionDistance(to, goal), m});
        }
      }
    }
    result.stats.iterations = expansions;
    result.stats.tree_size = expansions;
    if (result.trajectory.empty()) {
      result.status = search.cancelled() ? PlanStatus::kCancelled : PlanStatus::kIterationLimit;
      result.message = "no path to the goal within " + std::to_string(expansions) + " cells";
      return result;
    }
    result.status = PlanStatus::kSolved;
    result.message = "solved";
    finishPlan(p, search.smooth, result);
    return result;
  }

 private:
  struct Node {
    parksim::Pose2 pose;
    double cost = 0.0;
    long parent = -1;
    parksim::Trajectory edge;  // from the parent, at rest at both ends
    bool closed_ = false;
  };

  static long cellOf(double v, double min, double cell, long n) {
    return std::clamp(static_cast<long>((v - min) / cell), 0L, n - 1);
  }

  // A rest-to-rest trajectory from `from` to exactly `to`, valid for the problem.
  static bool join(const parksim::PlanningProblem& p, const parksim::Pose2& from,
                   const parksim::Pose2& to, parksim::Trajectory& out) {
    parksim::SteerResult r = p.steering.steer(from, {}, to, parksim::SteerMode::kExact);
    if (!r.reached || !p.validator.isValid(r.trajectory)) return false;
    out = std::move(r.trajectory);
    return true;
  }

  static parksim::Trajectory pathTo(const std::vector<Node>& nodes, long n) {
    std::vector<long> chain;
    for (long k = n; k > 0; k = nodes[k].parent) chain.push_back(k);
    parksim::Trajectory path;
    path.points.push_back({0.0, nodes[0].pose, {}});
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) path.append(nodes[*it].edge);
    return path;
  }

  GridDef def_;
};

void bind(GridDef& d, parksim::ParamSet& s) {
  s.add("cell_m", &d.cell_m, "grid cell, m; 0: half the footprint's radius", 0.0, 100.0);
}

}  // namespace

parksim::PlannerEntry gridPlanner() {
  parksim::PlannerInfo info;
  info.name = "example";
  info.description = "A* over a grid of positions joined by the steering function (a plugin)";
  info.uses_steering = true;
  return parksim::plannerEntry<GridPlanner>(std::move(info), GridDef{}, &bind);
}

}  // namespace example
