#pragma once
// Holm's step-down correction (Holm 1979) for testing many groups and metrics at once: with
// adjusted p-values compared against the level alpha, the chance of any false alarm over the
// whole family stays at most alpha whatever the tests' dependence, and it rejects everything
// Bonferroni rejects, often more.

#include <vector>

namespace parksim {

/// Holm-adjusted p-values, in the order of `p`: with p sorted ascending as p(1) <= ... <= p(m),
/// adjusted p(i) = max over j <= i of min(1, (m - j + 1) p(j)). Ties keep their input order.
std::vector<double> holmAdjusted(const std::vector<double>& p);

}  // namespace parksim
