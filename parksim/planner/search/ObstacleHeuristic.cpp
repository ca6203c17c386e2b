#include "parksim/planner/search/ObstacleHeuristic.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "parksim/core/io/Error.h"

namespace parksim {

ObstacleHeuristic::ObstacleHeuristic(const MotionValidator& validator, const LotBounds& lot,
                                     double cell_m, const Pose2& goal)
    : lot_(lot), cell_(cell_m) {
  build(
      [&](double x, double y) {
        for (int h = 0; h < 8; ++h) {
          if (validator.isValid(Pose2{x, y, h * kPi / 4.0})) return true;
        }
        return false;
      },
      goal);
}

ObstacleHeuristic::ObstacleHeuristic(const std::function<bool(double, double)>& fits,
                                     const LotBounds& lot, double cell_m, const Pose2& goal)
    : lot_(lot), cell_(cell_m) {
  build(fits, goal);
}

void ObstacleHeuristic::build(const std::function<bool(double, double)>& fits, const Pose2& goal) {
  const LotBounds& lot = lot_;
  const double cell_m = cell_;
  if (!(cell_m > 0.0)) throw Error("obstacle heuristic: cell size must be positive");
  nx_ = std::max(1, static_cast<int>(std::ceil((lot.x_max_m - lot.x_min_m) / cell_m)));
  ny_ = std::max(1, static_cast<int>(std::ceil((lot.y_max_m - lot.y_min_m) / cell_m)));
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<char> free(static_cast<std::size_t>(nx_) * ny_, 0);
  for (int j = 0; j < ny_; ++j) {
    for (int i = 0; i < nx_; ++i) {
      const double x = std::min(lot.x_min_m + (i + 0.5) * cell_m, lot.x_max_m);
      const double y = std::min(lot.y_min_m + (j + 0.5) * cell_m, lot.y_max_m);
      if (fits(x, y)) {
        free[static_cast<std::size_t>(j) * nx_ + i] = 1;
        ++free_cells_;
      }
    }
  }
  dist_.assign(free.size(), inf);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  const int g = index(goal.x, goal.y);
  dist_[g] = 0.0;
  free[g] = 1;  // the goal pose itself is valid: let the search leave its cell
  open.push({0.0, g});
  const double diag = std::sqrt(2.0) * cell_m;
  while (!open.empty()) {
    const auto [d, c] = open.top();
    open.pop();
    if (d > dist_[c] || !free[c]) continue;
    const int ci = c % nx_;
    const int cj = c / nx_;
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (di == 0 && dj == 0) continue;
        const int i = ci + di;
        const int j = cj + dj;
        if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
        const int n = j * nx_ + i;
        const double nd = d + (di != 0 && dj != 0 ? diag : cell_m);
        if (nd < dist_[n]) {
          dist_[n] = nd;
          open.push({nd, n});
        }
      }
    }
  }
}

int ObstacleHeuristic::index(double x, double y) const {
  const int i = std::clamp(static_cast<int>(std::floor((x - lot_.x_min_m) / cell_)), 0, nx_ - 1);
  const int j = std::clamp(static_cast<int>(std::floor((y - lot_.y_min_m) / cell_)), 0, ny_ - 1);
  return j * nx_ + i;
}

double ObstacleHeuristic::distance(double x, double y) const { return dist_[index(x, y)]; }

}  // namespace parksim
