#pragma once
// An episode's outcome as the facts its record is read from (results/EpisodeRecord.h): the
// plan, the measurements and the verdict, of the whole request or of one realisation.

#include <cstddef>

#include "parksim/pipeline/EpisodeOutcome.h"
#include "parksim/results/tables/EpisodeRecord.h"

namespace parksim {

/// Views into `outcome` (which must outlive them): the plan, the first realisation's
/// measurements (none when nothing was driven), the verdict on the whole request and the
/// world's content hash.
EpisodeFacts outcomeFacts(const EpisodeOutcome& outcome);

/// The same for realisation `index` (< outcome.realisations.size()): its measurements and its
/// own verdict.
EpisodeFacts realisationFacts(const EpisodeOutcome& outcome, std::size_t index);

}  // namespace parksim
