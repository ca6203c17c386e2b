#pragma once
// An episode's page (pages/EpisodePage.h), report.html, written with its other files: by
// `parksim run` and `parksim plan` into --out, by every episode a sweep keeps into its folder,
// by Python's run() into out_dir.

#include <string>

#include "parksim/pipeline/EpisodeOutcome.h"

namespace parksim {

/// Writes `dir`/report.html for the outcome and adds "report.html" to its files. Throws Error.
void writeEpisodeReport(const std::string& dir, EpisodeOutcome& out);

}  // namespace parksim
