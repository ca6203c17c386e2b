#pragma once
// Hybrid A*'s obstacle-aware heuristic: the shortest 8-connected grid distance from each cell
// to the goal, around cells where the robot fits in no heading. A cell is free when the motion
// validator accepts the footprint at its centre in at least one of eight headings (so the check
// is Bullet's exact one, with the validator's margin and lot bounds). Blocked cells receive a
// distance from their neighbours but pass none on, so poses near obstacles still get a value.

#include <functional>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/motion/MotionValidator.h"

namespace parksim {

class ObstacleHeuristic {
 public:
  /// Builds the distance field over `lot` with square cells of `cell_m`, from `goal`.
  ObstacleHeuristic(const MotionValidator& validator, const LotBounds& lot, double cell_m,
                    const Pose2& goal);
  /// As above with `fits(x, y)` saying whether a cell centre is free (FootprintFit.h) instead of
  /// the validator's eight footprint queries.
  ObstacleHeuristic(const std::function<bool(double, double)>& fits, const LotBounds& lot,
                    double cell_m, const Pose2& goal);

  /// Grid distance from the cell of (x, y) to the goal, m; infinity where the goal is
  /// unreachable.
  double distance(double x, double y) const;

  int freeCells() const { return free_cells_; }

 private:
  void build(const std::function<bool(double, double)>& fits, const Pose2& goal);
  int index(double x, double y) const;

  LotBounds lot_;
  double cell_;
  int nx_ = 0;
  int ny_ = 0;
  int free_cells_ = 0;
  std::vector<double> dist_;
};

}  // namespace parksim
