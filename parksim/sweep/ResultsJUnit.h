#pragma once
// A sweep's results table as a JUnit report (results/JUnitReport.h): `parksim sweep --junit`
// and `parksim report --junit`, so a CI page lists every episode as a test, grouped as
// `parksim report` groups them.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/results/JUnitReport.h"

namespace parksim {

/// One test suite per world x planner configuration (plannerLabel) x realism, named
/// "<world> / <planner> / <realism>", in that order; one test case per row, named
/// "seed=S noise_seed=N" (with " start=dx,dy,dyaw" and " goal=..." when offset) and the episode
/// id, sorted by seed, noise seed and id. A row that did not meet its tolerance fails with its
/// `failure` line as the message and its `status` as the type. Properties: episode_id, the
/// parameter columns (world, world_file, planner, ..., goal_dyaw_deg) and status. Time: the
/// row's episode_wall_s. `name` names the whole report (the sweep's name).
JUnitReport resultsJUnit(const std::vector<nlohmann::ordered_json>& rows, const std::string& name);

}  // namespace parksim
