#pragma once
// Internal to the planners that search in time over (x, y, heading) cells (TimeAStar.h,
// CarAStar.h): the one weighted A* loop both run in one window. A node keeps its continuous
// pose; a cell is closed once a node in it is expanded; each expansion may end the search with
// an analytic curve to a target; an obstacle grid bounds the heuristic. Coarse first; when that
// expands every reachable cell of the window, once more with the fine zone around the poses it
// grows from, and once more finer. A node waits keyed by the grid's bound until it comes first;
// only then is its model heuristic (a Reeds-Shepp or Balkcom-Mason optimum, most of a search's
// time) computed and the node queued again if that raises its key: the nodes expand in the
// same order as with every heuristic computed on arrival, for fewer heuristics. What differs
// between a differential drive and a car (the moves, what a junction between two moves costs, the
// heuristic's free-space term, the analytic curve, the cell sizes) is the Model's (runCellSearch).

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/search/FootprintFit.h"
#include "parksim/planner/search/ObstacleHeuristic.h"
#include "parksim/planner/search/SearchCells.h"
#include "parksim/planner/search/SearchWindow.h"

namespace parksim::detail {

using SearchClock = std::chrono::steady_clock;

inline double secondsSince(SearchClock::time_point since) {
  return std::chrono::duration<double>(SearchClock::now() - since).count();
}

/// What one search in one window is given besides its model.
struct CellSearchConfig {
  LotBounds window;  ///< nodes stay inside; the heuristic grid covers it
  const MotionValidator* validator = nullptr;
  /// The heuristic grid's free test; null: the validator's footprint queries (slower).
  const FootprintFit* fit = nullptr;
  double weight = 1.0;  ///< heuristic weight (>= 1): f = g + weight * h
  /// Poses the heuristic grid sees no way from are left out. The grid tests cell centres only,
  /// so a passage narrower than a cell may hide from it: a search that finds nothing with this
  /// tries again without.
  bool trust_grid = true;
  long max_expansions = 0;
  /// Wall-time end of the search; time_point::max() for none.
  SearchClock::time_point deadline = SearchClock::time_point::max();
  /// Stops the search like the deadline when set and true (SearchDef::cancel).
  const std::atomic<bool>* cancel = nullptr;
  const PlanProgress* progress = nullptr;
  long progress_offset = 0;  ///< expansions of earlier searches, for the progress display
  long progress_budget = 0;
};

struct CellSearchOutcome {
  enum class Status {
    kFound,
    kExhausted,  ///< every reachable cell of the window was expanded
    kBudget,     ///< max_expansions reached
    kTimeLimit,
  };
  Status status = Status::kExhausted;
  /// Found: the path from the start pose in driving order.
  std::vector<PathPiece> pieces;
  long expansions = 0;
  long nodes = 0;
  long analytic_attempts = 0;
  double heuristic_s = 0.0;  ///< building the obstacle heuristic's grid
  double analytic_s = 0.0;   ///< analytic expansions (steering and validating)
  double collision_s = 0.0;  ///< validating moves
};

/// The cells and analytic-expansion schedule a Model gives the loop for a window.
struct CellSearchLayout {
  CellSize coarse;
  double fine_zone_m = 0.0;  ///< around the sources; 0: never finer
  double grid_cell_m = 0.0;  ///< the obstacle grid's cells (at least window / max cells)
  /// The analytic expansion is tried from every node whose heuristic is below this, s, and
  /// from every analytic_interval-th expanded node otherwise.
  double analytic_near_s = 0.0;
  int analytic_interval = 1;
};

// A Model has:
//   using Move (members primitive, piece: in the search's direction, time_s) and Arrival (what
//     the move into a node leaves for the junction to the next; Arrival{} at the sources);
//   const RobotDef& robot() const;
//   CellSearchLayout layout(const LotBounds& window) const;
//   CellSize fineLevel(int level): makes the fine moves of level 1, 2, ... and gives their cells;
//   const std::vector<Move>& moves(bool fine) const;
//   double junction(const Arrival& from, const Move& move) const: the time a junction costs;
//   Arrival arrival(const Move& move) const;
//   double heuristic(const Pose2& p, double grid_m) const: seconds to the nearest target, with
//     the obstacle grid's distance (at least 0);
//   double gridHeuristic(double grid_m) const: a cheap bound, never above heuristic(p, grid_m);
//   std::vector<PathPiece> curve(const Pose2& from, const Pose2& target) const.
template <class Model>
class CellSearch {
 public:
  CellSearch(const CellSearchConfig& c, Model& model, CellSize coarse, double fine_zone_m,
             const std::vector<Pose2>& sources, const std::vector<Pose2>& targets)
      : c_(c),
        model_(model),
        validator_(*c.validator),
        targets_(targets),
        cell_keys_(c.window, coarse, model.fineLevel(1), fine_zone_m, sources) {}

  /// Searches from the sources toward the targets; `backward`: the result is driven the other
  /// way round (from the targets' start).
  CellSearchOutcome run(bool backward, double grid_cell_m, double analytic_near_s,
                        int analytic_interval);

 private:
  using Move = typename Model::Move;
  using Arrival = typename Model::Arrival;
  struct Node {
    Pose2 pose;
    double g = 0.0;
    int parent = -1;
    int move = -1;
    bool fine_move = false;
    Arrival arrival{};  // of the move into the node
    double grid = 0.0;  // gridDistance of its pose
    bool exact = true;  // queued with its model heuristic (else with gridHeuristic's bound)
  };
  struct Cell {
    double g = std::numeric_limits<double>::infinity();  // best node waiting or expanded
    bool closed = false;
  };
  using Item = std::pair<double, int>;  // f, node; ties by node id (deterministic)

  double gridDistance(const Pose2& p) const;
  void reset();
  bool expandNext();
  bool tryAnalytic(int id, double h);
  void pushChildren(int id);
  bool edgeValid(const Node& n);
  std::vector<PathPiece> pathTo(int id) const;
  bool stopped() const {
    return SearchClock::now() > c_.deadline ||
           (c_.cancel != nullptr && c_.cancel->load(std::memory_order_relaxed));
  }

  const CellSearchConfig& c_;
  Model& model_;
  const MotionValidator& validator_;
  std::vector<Pose2> targets_;
  SearchCells cell_keys_;
  std::unique_ptr<ObstacleHeuristic> grid_;
  double grid_slack_m_ = 0.0;
  double analytic_near_s_ = 0.0;
  int analytic_interval_ = 1;

  std::vector<Node> nodes_;
  std::unordered_map<std::int64_t, Cell> cells_;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open_;
  std::vector<PathPiece> analytic_;
  int reached_ = -1;
  CellSearchOutcome out_;
};

// The grid distance around obstacles less one cell diagonal (the grid's own slack), for the
// model's heuristic. Infinite where the grid sees no way, unless it is not trusted
// (CellSearchConfig::trust_grid): then 0, and the model's free-space term alone counts.
template <class Model>
double CellSearch<Model>::gridDistance(const Pose2& p) const {
  const double grid = grid_->distance(p.x, p.y) - grid_slack_m_;
  if (!std::isfinite(grid) && !c_.trust_grid) return 0.0;
  return grid;
}

template <class Model>
void CellSearch<Model>::reset() {
  nodes_.clear();
  cells_.clear();
  open_ = {};
  for (const Pose2& p : cell_keys_.sources()) {
    const std::int64_t k = cell_keys_.key(p);
    if (cells_.count(k)) continue;
    const double grid = gridDistance(p);
    if (!std::isfinite(grid)) continue;
    cells_[k].g = 0.0;
    open_.push({c_.weight * model_.heuristic(p, grid), static_cast<int>(nodes_.size())});
    nodes_.push_back({p, 0.0, -1, -1, false, Arrival{}, grid, true});
  }
}

template <class Model>
bool CellSearch<Model>::edgeValid(const Node& n) {
  if (n.parent < 0) return true;
  const SearchClock::time_point t0 = SearchClock::now();
  const bool ok = validator_.isValid(
      geometryOf(nodes_[n.parent].pose, {model_.moves(n.fine_move)[n.move].piece}, model_.robot()));
  out_.collision_s += secondsSince(t0);
  return ok;
}

template <class Model>
bool CellSearch<Model>::tryAnalytic(int id, double h) {
  const long n = out_.expansions;
  if (!(h < analytic_near_s_) && analytic_interval_ > 1 && n % analytic_interval_ != 1) {
    return false;
  }
  const SearchClock::time_point t0 = SearchClock::now();
  const Pose2 from = nodes_[id].pose;
  for (const Pose2& t : targets_) {
    ++out_.analytic_attempts;
    std::vector<PathPiece> curve = model_.curve(from, t);
    if (validator_.isValid(geometryOf(from, curve, model_.robot()))) {
      analytic_ = std::move(curve);
      reached_ = id;
      break;
    }
  }
  out_.analytic_s += secondsSince(t0);
  return reached_ >= 0;
}

template <class Model>
void CellSearch<Model>::pushChildren(int id) {
  const Node n = nodes_[id];
  const bool fine = cell_keys_.inFineZone(n.pose);
  const std::vector<Move>& moves = model_.moves(fine);
  for (int m = 0; m < static_cast<int>(moves.size()); ++m) {
    const Move& move = moves[m];
    const Pose2 next = applyPrimitive(n.pose, move.primitive);
    if (!c_.window.contains(next.x, next.y)) continue;
    const std::int64_t k = cell_keys_.key(next);
    auto it = cells_.find(k);
    if (it != cells_.end() && it->second.closed) continue;
    const double g = n.g + move.time_s + model_.junction(n.arrival, move);
    if (it != cells_.end() && it->second.g <= g) continue;
    const double grid = gridDistance(next);
    if (!std::isfinite(grid)) continue;
    cells_[k].g = g;
    open_.push({g + c_.weight * model_.gridHeuristic(grid), static_cast<int>(nodes_.size())});
    nodes_.push_back({next, g, id, m, fine, model_.arrival(move), grid, false});
  }
}

// Expands the best waiting node; false when the search should stop (found, out of nodes).
template <class Model>
bool CellSearch<Model>::expandNext() {
  while (!open_.empty()) {
    const auto [f, id] = open_.top();
    open_.pop();
    Node& n = nodes_[id];
    Cell& cell = cells_[cell_keys_.key(n.pose)];
    if (cell.closed) continue;
    if (!n.exact) {
      // First in the queue by the grid's bound: its own key now. A node worse than its cell's
      // best waits too (the best may fail its edge check and give the cell back).
      n.exact = true;
      const double exact = n.g + c_.weight * model_.heuristic(n.pose, n.grid);
      if (exact > f) {
        open_.push({exact, id});
        continue;
      }
    }
    if (n.g > cell.g) continue;
    if (!edgeValid(n)) {
      cell.g = std::numeric_limits<double>::infinity();  // others may reach the cell after all
      continue;
    }
    cell.closed = true;
    ++out_.expansions;
    if (c_.progress && *c_.progress) {
      (*c_.progress)(c_.progress_offset + out_.expansions, c_.progress_budget);
    }
    if (tryAnalytic(id, (f - nodes_[id].g) / c_.weight)) return false;
    pushChildren(id);
    return true;
  }
  return false;
}

template <class Model>
std::vector<PathPiece> CellSearch<Model>::pathTo(int id) const {
  std::vector<int> chain;
  for (int i = id; nodes_[i].parent >= 0; i = nodes_[i].parent) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<PathPiece> pieces;
  for (int i : chain) pieces.push_back(model_.moves(nodes_[i].fine_move)[nodes_[i].move].piece);
  pieces.insert(pieces.end(), analytic_.begin(), analytic_.end());
  return pieces;
}

template <class Model>
CellSearchOutcome CellSearch<Model>::run(bool backward, double grid_cell_m, double analytic_near_s,
                                         int analytic_interval) {
  analytic_near_s_ = analytic_near_s;
  analytic_interval_ = analytic_interval;
  const SearchClock::time_point t0 = SearchClock::now();
  grid_ = c_.fit ? std::make_unique<ObstacleHeuristic>(
                       [&](double x, double y) { return c_.fit->fitsSomeHeading(x, y); }, c_.window,
                       grid_cell_m, targets_.front())
                 : std::make_unique<ObstacleHeuristic>(validator_, c_.window, grid_cell_m,
                                                       targets_.front());
  grid_slack_m_ = std::sqrt(2.0) * grid_cell_m;
  out_.heuristic_s += secondsSince(t0);
  // Coarse, then the fine zone, then once more finer: a slot tighter than the fine zone's
  // resolution is searched finer before the search gives up.
  for (int attempt = 0; attempt < 3 && reached_ < 0; ++attempt) {
    if (attempt >= 1) {
      if (cell_keys_.fineZone_m() <= 0.0) break;
      cell_keys_.enableFineZone();
      cell_keys_.setFine(model_.fineLevel(attempt));
    }
    reset();
    while (expandNext()) {
      const bool budget = out_.expansions >= c_.max_expansions;
      if (budget || stopped()) {
        out_.status =
            budget ? CellSearchOutcome::Status::kBudget : CellSearchOutcome::Status::kTimeLimit;
        out_.nodes += static_cast<long>(nodes_.size());
        return std::move(out_);
      }
    }
    out_.nodes += static_cast<long>(nodes_.size());
  }
  if (reached_ < 0) {
    out_.status = CellSearchOutcome::Status::kExhausted;
    return std::move(out_);
  }
  std::vector<PathPiece> pieces = pathTo(reached_);
  if (backward) {
    // Driven the other way round: the pieces in reverse order, each with its wheels reversed.
    std::reverse(pieces.begin(), pieces.end());
    for (PathPiece& p : pieces) p.direction = {-p.direction.left_radps, -p.direction.right_radps};
  }
  for (const PathPiece& p : pieces) appendPiece(out_.pieces, p);
  out_.status = CellSearchOutcome::Status::kFound;
  return std::move(out_);
}

/// One search in one window: `model` gives the moves, costs, heuristic and curves; the loop
/// above runs from `sources` toward `targets`.
template <class Model>
CellSearchOutcome runCellSearch(const CellSearchConfig& config, Model& model,
                                const std::vector<Pose2>& sources,
                                const std::vector<Pose2>& targets, bool backward) {
  const CellSearchLayout l = model.layout(config.window);
  CellSearch<Model> search(config, model, l.coarse, l.fine_zone_m, sources, targets);
  return search.run(backward, l.grid_cell_m, l.analytic_near_s, l.analytic_interval);
}

/// Searches (`run(config)`, e.g. runCellSearch) in a window around `start` and `goal` with
/// margin `margin_m`, twice as wide each time a search expands every reachable cell of its
/// window, up to the lot; once the lot is searched, once more without trusting the heuristic's
/// grid. Adds each search's counts and times to `stats`; `margin_m` ends at the last margin.
template <class Run>
CellSearchOutcome searchWidening(CellSearchConfig& config, const LotBounds& lot, const Pose2& start,
                                 const Pose2& goal, double& margin_m, PlanStats& stats, Run run) {
  while (true) {
    config.window = searchWindow(lot, start, goal, margin_m);
    config.progress_offset = stats.iterations;
    CellSearchOutcome out = run();
    stats.iterations += static_cast<int>(out.expansions);
    stats.tree_size += static_cast<int>(out.nodes);
    stats.goal_attempts += static_cast<int>(out.analytic_attempts);
    stats.times.heuristic_s += out.heuristic_s;
    stats.times.goal_check_s += out.analytic_s;
    stats.times.collision_s += out.collision_s;
    if (out.status != CellSearchOutcome::Status::kExhausted) return out;
    if (coversLot(config.window, lot)) {
      if (!config.trust_grid) return out;
      config.trust_grid = false;  // a passage may have hidden from the grid: look there too
      continue;
    }
    margin_m *= 2.0;  // hemmed in by the window: look wider
  }
}

}  // namespace parksim::detail
