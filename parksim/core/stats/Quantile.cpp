#include "parksim/core/stats/Quantile.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"

namespace parksim {

double quantileSorted7(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) throw Error("quantile of no values");
  if (!(q >= 0.0 && q <= 1.0)) throw Error("quantile: q must be in [0, 1]");
  const double h = q * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[lo + 1] - sorted[lo]);
}

double quantile7(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return quantileSorted7(values, q);
}

}  // namespace parksim
