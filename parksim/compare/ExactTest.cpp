#include "parksim/compare/ExactTest.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

double logChoose(int n, int k) {
  return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
}

// Sums the probabilities in log space from the largest term, so tails of 1e-300 stay exact
// enough and a sum of many terms does not lose the small ones.
double sumOfExp(const std::vector<double>& logs) {
  if (logs.empty()) return 0.0;
  const double top = *std::max_element(logs.begin(), logs.end());
  double s = 0.0;
  for (const double l : logs) s += std::exp(l - top);
  return std::min(1.0, std::exp(top) * s);
}

}  // namespace

double fisherLowerPValue(int baseline_met, int baseline_n, int candidate_met, int candidate_n) {
  if (baseline_met < 0 || candidate_met < 0 || baseline_met > baseline_n ||
      candidate_met > candidate_n) {
    throw Error("Fisher's test: counts must satisfy 0 <= met <= n");
  }
  if (baseline_n == 0 || candidate_n == 0) return 1.0;
  const int total = baseline_n + candidate_n;
  const int met = baseline_met + candidate_met;
  // The candidate's met count X given the margins: P(X = x) = C(met, x) C(total - met,
  // candidate_n - x) / C(total, candidate_n), for x from max(0, candidate_n - (total - met)).
  const int lo = std::max(0, candidate_n - (total - met));
  std::vector<double> logs;
  for (int x = lo; x <= candidate_met; ++x) {
    logs.push_back(logChoose(met, x) + logChoose(total - met, candidate_n - x) -
                   logChoose(total, candidate_n));
  }
  return sumOfExp(logs);
}

double mcnemarWorsePValue(int worse, int better) {
  if (worse < 0 || better < 0) throw Error("McNemar's test: counts must not be negative");
  const int n = worse + better;
  if (n == 0) return 1.0;
  std::vector<double> logs;
  for (int k = worse; k <= n; ++k) logs.push_back(logChoose(n, k) - n * std::log(2.0));
  return sumOfExp(logs);
}

}  // namespace parksim
