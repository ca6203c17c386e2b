#pragma once
// Sample quantiles for comparisons: linear interpolation between order statistics (Hyndman and
// Fan's type 7, NumPy's and R's default), so the quantile moves smoothly when the values do and
// a bootstrap of it is not stuck on single values as nearest-rank quantiles are.

#include <vector>

namespace parksim {

/// The q-quantile (0 <= q <= 1) of ascending `sorted` values: sorted[h] + (h - floor(h)) *
/// (sorted[h + 1] - sorted[h]) at h = q (n - 1). Throws Error when empty or q is outside [0, 1].
double quantileSorted7(const std::vector<double>& sorted, double q);

/// The same of unsorted `values` (sorted on a copy).
double quantile7(std::vector<double> values, double q);

}  // namespace parksim
