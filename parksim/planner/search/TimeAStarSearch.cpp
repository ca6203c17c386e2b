#include "parksim/planner/search/TimeAStarSearch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <unordered_map>

#include "parksim/core/model/Geometry.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/motion/TimeCost.h"
#include "parksim/planner/search/FootprintFit.h"
#include "parksim/planner/search/ObstacleHeuristic.h"
#include "parksim/planner/search/SearchCells.h"
#include "parksim/planner/search/TimeAStar.h"
#include "parksim/planner/steering/BalkcomMason.h"

namespace parksim::detail {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// A move and what it costs to drive, precomputed.
struct Move {
  MotionPrimitive primitive;
  PathPiece piece;  // in the search's direction
  double time_s;
};

std::vector<Move> movesOf(const std::vector<MotionPrimitive>& primitives, const RobotDef& robot,
                          const TimeCostModel& cost) {
  std::vector<Move> moves;
  for (const MotionPrimitive& p : primitives) {
    const PathPiece piece = pieceOf(p, robot);
    moves.push_back({p, piece, cost.pieceTime(piece)});
  }
  return moves;
}

class Search {
 public:
  Search(const TimeSearchConfig& c, const std::vector<Pose2>& sources,
         const std::vector<Pose2>& targets)
      : c_(c),
        def_(*c.def),
        validator_(*c.validator),
        cost_(c.limits),
        targets_(targets),
        half_base_(0.5 * c.robot.wheel_base_m),
        speed_mps_(c.limits.max_wheel_speed_radps * c.robot.wheel_radius_m) {
    const double radius = footprintRadius(c.robot);
    cell_ = def_.cell_m > 0.0 ? def_.cell_m : 0.25 * radius;
    const double step = def_.step_m > 0.0 ? def_.step_m : 1.5 * cell_;
    coarse_ = movesOf(makePrimitives(step, def_.arc_radii_m, def_.spin_angles_rad), c.robot, cost_);
    cell_keys_ = SearchCells(c.window, {cell_, def_.heading_bins},
                             {def_.fine_cell_m, def_.fine_heading_bins},
                             def_.fine_zone_m < 0.0 ? 2.0 * radius : def_.fine_zone_m, sources);
    setFineLevel(1);
  }

  TimeSearchOutcome run(bool backward);

 private:
  struct Node {
    Pose2 pose;
    double g = 0.0;
    int parent = -1;
    int move = -1;
    bool fine_move = false;
    WheelSpeeds direction;  // of the move into the node; rest at the sources
  };
  struct Cell {
    double g = std::numeric_limits<double>::infinity();  // best node waiting or expanded
    bool closed = false;
  };
  using Item = std::pair<double, int>;  // f, node; ties by node id (deterministic)

  void setFineLevel(int level);
  double heuristic(const Pose2& p) const;
  void buildHeuristic();
  void reset();
  bool expandNext();
  bool tryAnalytic(int id, double h);
  void pushChildren(int id);
  bool edgeValid(const Node& n);
  std::vector<PathPiece> pathTo(int id) const;

  const TimeSearchConfig& c_;
  const TimeAStarDef& def_;
  const MotionValidator& validator_;
  TimeCostModel cost_;
  std::vector<Pose2> targets_;
  double half_base_;
  double speed_mps_;
  double cell_ = 0.0;
  SearchCells cell_keys_;
  std::vector<Move> coarse_;
  std::vector<Move> fine_;
  std::unique_ptr<ObstacleHeuristic> grid_;
  double grid_slack_m_ = 0.0;

  std::vector<Node> nodes_;
  std::unordered_map<std::int64_t, Cell> cells_;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open_;
  std::vector<PathPiece> analytic_;
  int reached_ = -1;
  TimeSearchOutcome out_;
};

// The fine zone at `level` (1, 2, ...): TimeAStarDef's fine cells, moves and turns at level 1,
// each level halving cells, moves and turns and doubling the heading bins.
void Search::setFineLevel(int level) {
  const double scale = std::ldexp(1.0, 1 - level);
  cell_keys_.setFine(
      {scale * def_.fine_cell_m, static_cast<int>(std::lround(def_.fine_heading_bins / scale))});
  std::vector<double> spins;
  for (double a : def_.fine_spin_angles_rad) spins.push_back(scale * a);
  fine_ =
      movesOf(makePrimitives(scale * def_.fine_step_m, def_.arc_radii_m, spins), c_.robot, cost_);
}

// Seconds to the nearest target at full speed: the larger of the free-space optimum and the
// grid distance around obstacles (less one cell diagonal, the grid's own slack). Infinite where
// the grid sees no way, unless it is not trusted (TimeSearchConfig::trust_grid): then the
// free-space optimum alone.
double Search::heuristic(const Pose2& p) const {
  double grid = grid_->distance(p.x, p.y) - grid_slack_m_;
  if (!std::isfinite(grid)) {
    if (c_.trust_grid) return grid;
    grid = 0.0;
  }
  double free_space = std::numeric_limits<double>::infinity();
  for (const Pose2& t : targets_) {
    // No free-space optimum exceeds the distance plus two half turns: past that the grid's
    // detour decides, without solving for the optimum.
    if (grid >= positionDistance(p, t) + 2.0 * kPi * half_base_) return grid / speed_mps_;
    free_space = std::min(free_space, balkcomMasonCost(p, t, half_base_));
  }
  return std::max(free_space, grid) / speed_mps_;
}

void Search::buildHeuristic() {
  const Clock::time_point t0 = Clock::now();
  const double longer = std::max(cell_keys_.width_m(), cell_keys_.height_m());
  const double cell = std::max(cell_, longer / def_.max_heuristic_cells_per_side);
  grid_ = c_.fit
              ? std::make_unique<ObstacleHeuristic>(
                    [&](double x, double y) { return c_.fit->fitsSomeHeading(x, y); }, c_.window,
                    cell, targets_.front())
              : std::make_unique<ObstacleHeuristic>(validator_, c_.window, cell, targets_.front());
  grid_slack_m_ = std::sqrt(2.0) * cell;
  out_.heuristic_s += seconds(t0);
}

void Search::reset() {
  nodes_.clear();
  cells_.clear();
  open_ = {};
  for (const Pose2& p : cell_keys_.sources()) {
    const std::int64_t k = cell_keys_.key(p);
    if (cells_.count(k)) continue;
    const double h = heuristic(p);
    if (!std::isfinite(h)) continue;
    cells_[k].g = 0.0;
    open_.push({c_.weight * h, static_cast<int>(nodes_.size())});
    nodes_.push_back({p, 0.0, -1, -1, false, {}});
  }
}

bool Search::edgeValid(const Node& n) {
  if (n.parent < 0) return true;
  const Clock::time_point t0 = Clock::now();
  const std::vector<Move>& moves = n.fine_move ? fine_ : coarse_;
  const bool ok =
      validator_.isValid(geometryOf(nodes_[n.parent].pose, {moves[n.move].piece}, c_.robot));
  out_.collision_s += seconds(t0);
  return ok;
}

bool Search::tryAnalytic(int id, double h) {
  const long n = out_.expansions;
  if (!(h < def_.analytic_near_s) && def_.analytic_interval > 1 &&
      n % def_.analytic_interval != 1) {
    return false;
  }
  const Clock::time_point t0 = Clock::now();
  const Pose2 from = nodes_[id].pose;
  for (const Pose2& t : targets_) {
    ++out_.analytic_attempts;
    std::vector<PathPiece> curve = piecesOf(balkcomMasonPath(from, t, half_base_), c_.robot);
    if (validator_.isValid(geometryOf(from, curve, c_.robot))) {
      analytic_ = std::move(curve);
      reached_ = id;
      break;
    }
  }
  out_.analytic_s += seconds(t0);
  return reached_ >= 0;
}

void Search::pushChildren(int id) {
  const Node n = nodes_[id];
  const bool fine = cell_keys_.inFineZone(n.pose);
  const std::vector<Move>& moves = fine ? fine_ : coarse_;
  for (int m = 0; m < static_cast<int>(moves.size()); ++m) {
    const Move& move = moves[m];
    const Pose2 next = applyPrimitive(n.pose, move.primitive);
    if (!c_.window.contains(next.x, next.y)) continue;
    const std::int64_t k = cell_keys_.key(next);
    auto it = cells_.find(k);
    if (it != cells_.end() && it->second.closed) continue;
    const double g = n.g + move.time_s + cost_.junctionTime(n.direction, move.piece.direction);
    if (it != cells_.end() && it->second.g <= g) continue;
    const double h = heuristic(next);
    if (!std::isfinite(h)) continue;
    cells_[k].g = g;
    open_.push({g + c_.weight * h, static_cast<int>(nodes_.size())});
    nodes_.push_back({next, g, id, m, fine, move.piece.direction});
  }
}

// Expands the best waiting node; false when the search should stop (found, out of nodes, out
// of budget).
bool Search::expandNext() {
  while (!open_.empty()) {
    const auto [f, id] = open_.top();
    open_.pop();
    const Node& n = nodes_[id];
    Cell& cell = cells_[cell_keys_.key(n.pose)];
    if (cell.closed || n.g > cell.g) continue;
    if (!edgeValid(n)) {
      cell.g = std::numeric_limits<double>::infinity();  // others may reach the cell after all
      continue;
    }
    cell.closed = true;
    ++out_.expansions;
    if (c_.progress && *c_.progress) {
      (*c_.progress)(c_.progress_offset + out_.expansions, c_.progress_budget);
    }
    const double h = (f - nodes_[id].g) / c_.weight;
    if (tryAnalytic(id, h)) return false;
    pushChildren(id);
    return true;
  }
  return false;
}

std::vector<PathPiece> Search::pathTo(int id) const {
  std::vector<int> chain;
  for (int i = id; nodes_[i].parent >= 0; i = nodes_[i].parent) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<PathPiece> pieces;
  for (int i : chain) {
    const Node& n = nodes_[i];
    pieces.push_back((n.fine_move ? fine_ : coarse_)[n.move].piece);
  }
  pieces.insert(pieces.end(), analytic_.begin(), analytic_.end());
  return pieces;
}

TimeSearchOutcome Search::run(bool backward) {
  buildHeuristic();
  // Coarse, then the fine zone, then once more at half its cells and moves: a slot tighter
  // than the fine zone's resolution is searched finer before the search gives up.
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (attempt >= 1) {
      if (cell_keys_.fineZone_m() <= 0.0) break;
      cell_keys_.enableFineZone();
      setFineLevel(attempt);
    }
    reset();
    while (expandNext()) {
      if (out_.expansions >= c_.max_expansions) {
        out_.status = TimeSearchOutcome::Status::kBudget;
        out_.nodes += static_cast<long>(nodes_.size());
        return std::move(out_);
      }
      if (Clock::now() > c_.deadline ||
          (c_.cancel != nullptr && c_.cancel->load(std::memory_order_relaxed))) {
        out_.status = TimeSearchOutcome::Status::kTimeLimit;
        out_.nodes += static_cast<long>(nodes_.size());
        return std::move(out_);
      }
    }
    out_.nodes += static_cast<long>(nodes_.size());
    if (reached_ >= 0) break;
  }
  if (reached_ < 0) {
    out_.status = TimeSearchOutcome::Status::kExhausted;
    return std::move(out_);
  }
  std::vector<PathPiece> pieces = pathTo(reached_);
  if (backward) {
    // Driven the other way round: the pieces in reverse order, each with its wheels reversed.
    std::reverse(pieces.begin(), pieces.end());
    for (PathPiece& p : pieces) p.direction = {-p.direction.left_radps, -p.direction.right_radps};
  }
  for (const PathPiece& p : pieces) appendPiece(out_.pieces, p);
  out_.status = TimeSearchOutcome::Status::kFound;
  return std::move(out_);
}

}  // namespace

TimeSearchOutcome runTimeSearch(const TimeSearchConfig& config, const std::vector<Pose2>& sources,
                                const std::vector<Pose2>& targets, bool backward) {
  return Search(config, sources, targets).run(backward);
}

}  // namespace parksim::detail
