#include "parksim/planner/search/TimeAStarSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "parksim/core/model/Geometry.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/motion/TimeCost.h"
#include "parksim/planner/search/TimeAStar.h"
#include "parksim/planner/steering/BalkcomMason.h"

namespace parksim::detail {

namespace {

// The differential drive in the cell search: arcs, straights and spins; junctions priced by the
// wheels' speed changes; the free-space optimum of Balkcom and Mason; their curves.
class TimeModel {
 public:
  // A move and what it costs to drive, precomputed.
  struct Move {
    MotionPrimitive primitive;
    PathPiece piece;  // in the search's direction
    double time_s;
  };
  using Arrival = WheelSpeeds;  // the wheels of the move into a node; rest at the sources

  TimeModel(const TimeSearchConfig& c, const std::vector<Pose2>& targets)
      : c_(c),
        def_(*c.def),
        cost_(c.limits),
        targets_(targets),
        half_base_(0.5 * c.robot.wheel_base_m),
        speed_mps_(c.limits.max_wheel_speed_radps * c.robot.wheel_radius_m) {
    const double radius = footprintRadius(c.robot);
    cell_ = def_.cell_m > 0.0 ? def_.cell_m : 0.25 * radius;
    const double step = def_.step_m > 0.0 ? def_.step_m : 1.5 * cell_;
    coarse_ = movesOf(makePrimitives(step, def_.arc_radii_m, def_.spin_angles_rad));
    fine_zone_m_ = def_.fine_zone_m < 0.0 ? 2.0 * radius : def_.fine_zone_m;
  }

  const RobotDef& robot() const { return c_.robot; }

  CellSearchLayout layout(const LotBounds& window) const {
    const double longer =
        std::max(window.x_max_m - window.x_min_m, window.y_max_m - window.y_min_m);
    return {{cell_, def_.heading_bins},
            fine_zone_m_,
            std::max(cell_, longer / def_.max_heuristic_cells_per_side),
            def_.analytic_near_s,
            def_.analytic_interval};
  }

  // The fine zone at `level` (1, 2, ...): TimeAStarDef's fine cells, moves and turns at level
  // 1, each level halving cells, moves and turns and doubling the heading bins.
  CellSize fineLevel(int level) {
    const double scale = std::ldexp(1.0, 1 - level);
    std::vector<double> spins;
    for (double a : def_.fine_spin_angles_rad) spins.push_back(scale * a);
    fine_ = movesOf(makePrimitives(scale * def_.fine_step_m, def_.arc_radii_m, spins));
    return {scale * def_.fine_cell_m,
            static_cast<int>(std::lround(def_.fine_heading_bins / scale))};
  }

  const std::vector<Move>& moves(bool fine) const { return fine ? fine_ : coarse_; }
  double junction(const Arrival& from, const Move& move) const {
    return cost_.junctionTime(from, move.piece.direction);
  }
  Arrival arrival(const Move& move) const { return move.piece.direction; }

  // Seconds to the nearest target at full speed: the larger of the free-space optimum and the
  // grid distance.
  double heuristic(const Pose2& p, double grid) const {
    double free_space = std::numeric_limits<double>::infinity();
    for (const Pose2& t : targets_) {
      // No free-space optimum exceeds the distance plus two half turns: past that the grid's
      // detour decides, without solving for the optimum.
      if (grid >= positionDistance(p, t) + 2.0 * kPi * half_base_) return grid / speed_mps_;
      free_space = std::min(free_space, balkcomMasonCost(p, t, half_base_));
    }
    return std::max(free_space, grid) / speed_mps_;
  }
  double gridHeuristic(double grid) const { return grid / speed_mps_; }

  std::vector<PathPiece> curve(const Pose2& from, const Pose2& target) const {
    return piecesOf(balkcomMasonPath(from, target, half_base_), c_.robot);
  }

 private:
  std::vector<Move> movesOf(const std::vector<MotionPrimitive>& primitives) const {
    std::vector<Move> moves;
    for (const MotionPrimitive& p : primitives) {
      const PathPiece piece = pieceOf(p, c_.robot);
      moves.push_back({p, piece, cost_.pieceTime(piece)});
    }
    return moves;
  }

  const TimeSearchConfig& c_;
  const TimeAStarDef& def_;
  TimeCostModel cost_;
  std::vector<Pose2> targets_;
  double half_base_;
  double speed_mps_;
  double cell_ = 0.0;
  double fine_zone_m_ = 0.0;
  std::vector<Move> coarse_;
  std::vector<Move> fine_;
};

}  // namespace

TimeSearchOutcome runTimeSearch(const TimeSearchConfig& config, const std::vector<Pose2>& sources,
                                const std::vector<Pose2>& targets, bool backward) {
  TimeModel model(config, targets);
  return runCellSearch(config, model, sources, targets, backward);
}

}  // namespace parksim::detail
