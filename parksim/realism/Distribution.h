#pragma once
// Median, 95th percentile and maximum of a sample (the realisations of one plan under several
// noise seeds). The quantiles are parksim's one definition (core/stats/Quantile.h: type 7,
// linear between order statistics, NumPy's default), the ones the report, the pages and
// `parksim compare` give for the same values.

#include <vector>

namespace parksim {

struct Distribution {
  double median = 0.0;  ///< the 0.5-quantile: the mean of the two middle values for an even count
  double p95 = 0.0;     ///< the 0.95-quantile
  double max = 0.0;
};

/// Throws Error on an empty sample. NaNs sort last (they count as the worst values).
Distribution summarize(std::vector<double> values);

}  // namespace parksim
