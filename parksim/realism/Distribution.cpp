#include "parksim/realism/Distribution.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"

namespace parksim {

Distribution summarize(std::vector<double> values) {
  if (values.empty()) throw Error("distribution of no values");
  std::sort(values.begin(), values.end(), [](double a, double b) {
    if (std::isnan(a)) return false;
    if (std::isnan(b)) return true;
    return a < b;
  });
  const std::size_t n = values.size();
  Distribution d;
  d.median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(n)));
  d.p95 = values[std::max<std::size_t>(rank, 1) - 1];
  d.max = values.back();
  return d;
}

}  // namespace parksim
