#pragma once
// Exact tests of a drop in success rate, one-sided: is the candidate's rate lower than the
// baseline's? Exact (no normal approximation), so they hold for the small counts of a CI
// sweep (20 episodes, all or nearly all met).
//
// - Unpaired (two independent samples, e.g. other noise seeds): Fisher's exact test on the 2x2
//   table, conditional on its margins.
// - Paired (the same episodes run twice): McNemar's exact test, a binomial test on the
//   discordant pairs (met before and failed now, against failed before and met now). Pairs
//   that agree carry no evidence either way; with a deterministic simulation, unchanged code
//   gives no discordant pair at all.

namespace parksim {

/// Fisher's exact test, one-sided: P(X <= candidate_met) for X hypergeometric with the table's
/// margins. Small when the candidate met its tolerance less often than the baseline. 1 when
/// either sample is empty. Throws Error on negative counts or met > n.
double fisherLowerPValue(int baseline_met, int baseline_n, int candidate_met, int candidate_n);

/// McNemar's exact test, one-sided: P(B >= worse) for B ~ Binomial(worse + better, 1/2), where
/// `worse` pairs met in the baseline and fail in the candidate, `better` the reverse. 1 when
/// there are no discordant pairs. Throws Error on negative counts.
double mcnemarWorsePValue(int worse, int better);

}  // namespace parksim
