#include "parksim/compare/HolmCorrection.h"

#include <algorithm>
#include <numeric>

namespace parksim {

std::vector<double> holmAdjusted(const std::vector<double>& p) {
  const std::size_t m = p.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<double> adjusted(m);
  double running = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = order[k];
    running = std::max(running, std::min(1.0, static_cast<double>(m - k) * p[i]));
    adjusted[i] = running;
  }
  return adjusted;
}

}  // namespace parksim
