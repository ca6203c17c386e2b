#pragma once
// Median, 95th percentile and maximum of a sample (the realisations of one plan under several
// noise seeds). Percentiles are nearest-rank: p95 is the smallest value that at least 95 % of
// the sample do not exceed, so it is always one of the values.

#include <vector>

namespace parksim {

struct Distribution {
  double median = 0.0;  ///< middle value; the mean of the two middle ones for an even count
  double p95 = 0.0;
  double max = 0.0;
};

/// Throws Error on an empty sample. NaNs sort last (they count as the worst values).
Distribution summarize(std::vector<double> values);

}  // namespace parksim
