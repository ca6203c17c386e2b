#include "parksim/planner/search/ReachableBudget.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "parksim/core/model/Geometry.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/search/FootprintFit.h"

namespace parksim {

namespace {

constexpr double kMaxBudget = 1'000'000.0;

}  // namespace

double reachableFreeArea(const Scenario& s) {
  const LotBounds& lot = s.lot;
  const double w = lot.x_max_m - lot.x_min_m;
  const double h = lot.y_max_m - lot.y_min_m;
  const double cell =
      std::max(footprintRadius(s.robot), std::max(w, h) / kReachableGridCellsPerSide);
  const int nx = std::max(1, static_cast<int>(std::ceil(w / cell)));
  const int ny = std::max(1, static_cast<int>(std::ceil(h / cell)));
  const FootprintFit fit(s.obstacles, s.robot, placementMargin(s.robot));
  // 0 unknown, 1 free, 2 blocked: cells are tested as the fill reaches them.
  std::vector<char> state(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
  const auto index = [&](int i, int j) { return static_cast<std::size_t>(j) * nx + i; };
  const int i0 = std::clamp(static_cast<int>((s.start.x - lot.x_min_m) / cell), 0, nx - 1);
  const int j0 = std::clamp(static_cast<int>((s.start.y - lot.y_min_m) / cell), 0, ny - 1);
  std::vector<std::pair<int, int>> stack{{i0, j0}};
  state[index(i0, j0)] = 1;  // the start stands there
  double area = 0.0;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    // Cells at the lot's edge count with the part inside the lot.
    area += (std::min(lot.x_min_m + (i + 1) * cell, lot.x_max_m) - (lot.x_min_m + i * cell)) *
            (std::min(lot.y_min_m + (j + 1) * cell, lot.y_max_m) - (lot.y_min_m + j * cell));
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        const int a = i + di;
        const int b = j + dj;
        if (a < 0 || b < 0 || a >= nx || b >= ny || state[index(a, b)] != 0) continue;
        const double x = std::min(lot.x_min_m + (a + 0.5) * cell, lot.x_max_m);
        const double y = std::min(lot.y_min_m + (b + 0.5) * cell, lot.y_max_m);
        state[index(a, b)] = fit.fitsSomeHeading(x, y) ? 1 : 2;
        if (state[index(a, b)] == 1) stack.emplace_back(a, b);
      }
    }
  }
  return area;
}

int boundedBudget(double budget, int floor) {
  return static_cast<int>(std::min(kMaxBudget, std::max<double>(floor, std::ceil(budget))));
}

}  // namespace parksim
