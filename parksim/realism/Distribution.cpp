#include "parksim/realism/Distribution.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/core/stats/Quantile.h"

namespace parksim {

Distribution summarize(std::vector<double> values) {
  if (values.empty()) throw Error("distribution of no values");
  std::sort(values.begin(), values.end(), [](double a, double b) {
    if (std::isnan(a)) return false;
    if (std::isnan(b)) return true;
    return a < b;
  });
  Distribution d;
  d.median = quantileSorted7(values, 0.5);
  d.p95 = quantileSorted7(values, 0.95);
  d.max = values.back();
  return d;
}

}  // namespace parksim
