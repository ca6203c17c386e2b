#include "parksim/compare/Bootstrap.h"

#include <algorithm>

#include "parksim/core/io/Error.h"
#include "parksim/core/stats/Quantile.h"

namespace parksim {

namespace {

// Two indices per 64-bit draw, each from 32 random bits by multiply-shift (Lemire): no
// division, which made the draws most of a comparison's time.
void drawIndices(std::size_t n, std::mt19937_64& rng, std::vector<std::size_t>& out) {
  out.resize(n);
  const std::uint64_t range = n;
  for (std::size_t k = 0; k < n; k += 2) {
    const std::uint64_t bits = rng();
    out[k] = static_cast<std::size_t>(((bits & 0xFFFFFFFFu) * range) >> 32);
    if (k + 1 < n) out[k + 1] = static_cast<std::size_t>(((bits >> 32) * range) >> 32);
  }
}

double resampledQuantile(const std::vector<double>& values, const std::vector<std::size_t>& idx,
                         double q, std::vector<double>& scratch) {
  scratch.resize(idx.size());
  for (std::size_t k = 0; k < idx.size(); ++k) scratch[k] = values[idx[k]];
  std::sort(scratch.begin(), scratch.end());
  return quantileSorted7(scratch, q);
}

}  // namespace

std::vector<QuantilePair> bootstrapQuantiles(const std::vector<double>& baseline,
                                             const std::vector<double>& candidate, double q,
                                             bool paired, int resamples, std::mt19937_64& rng) {
  if (baseline.empty() || candidate.empty()) throw Error("bootstrap: an empty sample");
  if (baseline.size() > 0xFFFFFFFFu || candidate.size() > 0xFFFFFFFFu) {
    throw Error("bootstrap: more than 2^32 values in a sample");
  }
  if (paired && baseline.size() != candidate.size()) {
    throw Error("bootstrap: paired samples must have one length");
  }
  if (resamples < 1) throw Error("bootstrap: resamples must be at least 1");
  std::vector<QuantilePair> out(static_cast<std::size_t>(resamples));
  std::vector<std::size_t> idx_b;
  std::vector<std::size_t> idx_c;
  std::vector<double> scratch;
  for (QuantilePair& r : out) {
    drawIndices(baseline.size(), rng, idx_b);
    if (!paired) drawIndices(candidate.size(), rng, idx_c);
    r.baseline = resampledQuantile(baseline, idx_b, q, scratch);
    r.candidate = resampledQuantile(candidate, paired ? idx_b : idx_c, q, scratch);
  }
  return out;
}

double percentileOf(std::vector<double> replicates, double p) {
  return quantile7(std::move(replicates), p);
}

}  // namespace parksim
