#pragma once
// The default iteration budget of a lot from the free area its search can reach, not only the
// lot's size: a 30 x 15 m warehouse whose robot can reach 300 m^2 of aisles gets the budget of
// those aisles, and a large map whose start sits in one small room gets that room's. The area is
// the cells of a coarse grid over the lot (cells about the footprint's size, at most
// kReachableGridCellsPerSide a side) whose centre the robot fits on in some heading
// (FootprintFit.h), connected to the start's cell.

#include "parksim/core/model/Scenario.h"

namespace parksim {

/// Most cells a side of the reachable-area grid: the flood fill then costs a few tens of
/// milliseconds on the largest maps.
inline constexpr int kReachableGridCellsPerSide = 200;

/// The free area reachable from the scenario's start, m^2 (see above).
double reachableFreeArea(const Scenario& scenario);

/// `budget` rounded up and held to [floor, 1,000,000] (the largest --max-iterations): the
/// planners' default budgets from the reachable area (TimeAStarPlanner.cpp,
/// HybridAStarPlanner.cpp) go through it.
int boundedBudget(double budget, int floor);

}  // namespace parksim
