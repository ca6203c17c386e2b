#pragma once
// The bootstrap (Efron) of a quantile in two samples, baseline and candidate: many replicates
// of both quantiles, each computed on values drawn with replacement, from which a comparison
// takes confidence intervals and p-values of any function of the pair (a change, a ratio, an
// excess over a margin).
//
// Paired samples (the same episodes in both tables, element i of each from one episode) are
// resampled by episode: one draw of indices per replicate serves both, so what the episodes
// share (their plan, their world) cancels in the change. Unpaired samples (other noise seeds)
// are resampled each on its own.
//
// The generator is passed in and drawn from in a fixed order, so the same seed gives the same
// replicates on every platform (std::mt19937_64's sequence is fixed by the C++ standard, and
// each index comes from 32 of its bits by multiply-shift, whose bias for samples of n values
// is below n / 2^32).

#include <cstdint>
#include <random>
#include <vector>

namespace parksim {

/// One bootstrap replicate: the quantile in each resampled sample.
struct QuantilePair {
  double baseline = 0.0;
  double candidate = 0.0;
};

/// `resamples` replicates of the q-quantiles (quantile7) of `baseline` and `candidate`.
/// `paired` needs samples of one length. Throws Error on an empty sample, unequal lengths
/// when paired, or resamples < 1.
std::vector<QuantilePair> bootstrapQuantiles(const std::vector<double>& baseline,
                                             const std::vector<double>& candidate, double q,
                                             bool paired, int resamples, std::mt19937_64& rng);

/// The p-quantile of bootstrap replicate values (a percentile interval's end), as quantile7.
double percentileOf(std::vector<double> replicates, double p);

}  // namespace parksim
