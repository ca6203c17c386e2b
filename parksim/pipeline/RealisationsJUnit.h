#pragma once
// `parksim run --junit FILE`: an episode's outcome as a JUnit report (results/JUnitReport.h),
// so a CI job that runs one world shows each noise realisation as a test.

#include <string>

#include "parksim/pipeline/EpisodeOutcome.h"
#include "parksim/results/JUnitReport.h"

namespace parksim {

/// One test suite named "<world> / <planner> / <realism>", one test case per realisation
/// ("noise_seed=N"), failed with that realisation's own verdict line (message) and status
/// (type); a plan that failed is one failed case "plan". Each case's properties are the
/// episode's parameters (world, world_file, planner, steering, seed, max_iterations, timing,
/// tracking, realism, noise_seed) and its status; its time is the realisation's simulation wall
/// time. The suite's properties add the verdict on the whole request.
JUnitReport realisationsJUnit(const EpisodeOutcome& outcome);

}  // namespace parksim
