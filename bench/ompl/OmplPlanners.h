#pragma once
// OMPL's planners on a parksim scenario, asking the same footprint checker parksim's planners
// ask, for a side-by-side benchmark.
//
// OMPL seeds all its random number generators from one process-wide seed that can be set only
// once, before any planner exists (ompl::RNG::setSeed). So every run happens in a child
// process forked for it: the child sets the run's seed, plans, interpolates the path densely
// along the state space's own curves, and sends the result back through a pipe. The parent never
// creates an OMPL planner, sampler or RNG, and runs stay reproducible and independent.
//
// The state validity checker accepts a state when the reference point lies inside the lot (the
// state space's bounds) and the footprint, grown by `margin_m`, overlaps nothing. Motions are
// checked by OMPL's discrete motion validator (Reeds-Shepp: its Reeds-Shepp variant) at
// `segment_m` of state-space distance; that is OMPL's resolution, not a guarantee, so the dense
// path is returned for parksim's own check (bench/planning/PathCheck.h).

#include <cstdint>
#include <string>
#include <vector>

#include "bench/planning/PathCheck.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/results/reports/BenchRecord.h"

namespace parksim::bench {

enum class OmplPlanner { kRrt, kRrtConnect, kRrtStar };
enum class OmplSpace {
  kReedsShepp,  ///< forward and reverse arcs of a minimum turning radius: drivable
  kSe2,         ///< straight lines in (x, y, theta): slides sideways, for reference only
};

/// OMPL's class names: "RRT", "RRTConnect", "RRTstar".
const char* toString(OmplPlanner planner);
/// "reeds-shepp", "se2".
const char* toString(OmplSpace space);
std::vector<OmplPlanner> allOmplPlanners();
std::vector<OmplSpace> allOmplSpaces();
/// Parse the names above; throw Error otherwise.
OmplPlanner omplPlannerFromString(const std::string& name);
OmplSpace omplSpaceFromString(const std::string& name);

struct OmplRunDef {
  OmplPlanner planner = OmplPlanner::kRrtConnect;
  OmplSpace space = OmplSpace::kReedsShepp;
  /// OMPL's process-wide seed for this run; must be > 0 (OMPL ignores 0).
  std::uint32_t seed = 1;
  /// Wall-time limit, s. RRT and RRTConnect stop at their first exact solution or here;
  /// RRT* keeps improving its path until here.
  double time_limit_s = 1.0;
  /// Reeds-Shepp minimum turning radius, m.
  double turning_radius_m = 0.1;
  /// Longest motion OMPL's motion validator leaves unchecked, in state-space distance (m for
  /// Reeds-Shepp arcs; |dp| + 0.5 |dtheta| for SE2).
  double segment_m = 0.0005;
  /// Footprint growth in the validity checker, m.
  double margin_m = 0.0;
  /// Accepted state-space distance from the goal state.
  double goal_threshold = 0.001;
  /// Largest footprint-point step between two poses of the returned dense path, m.
  double dense_step_m = 0.0002;
};

struct OmplRunResult {
  bool solved = false;                 ///< an exact solution within the time limit
  std::string status;                  ///< OMPL's PlannerStatus text, or why the child failed
  int status_code = 0;                 ///< ompl::base::PlannerStatus::StatusType value
  double time_first_s = kNotMeasured;  ///< wall time to the first exact solution, s
  double time_total_s = kNotMeasured;  ///< wall time of solve(), s
  double cpu_total_s = kNotMeasured;   ///< CPU time of solve(), s
  double ompl_length = kNotMeasured;   ///< PathGeometric::length() in the space's metric
  long graph_states = -1;              ///< vertices of the planner's graph after the run
  std::vector<Pose2> waypoints;        ///< the solution path's states
  std::vector<Pose2> dense;            ///< interpolated between them along the space's curves
};

/// Runs one OMPL planner on `scenario` in a forked child process seeded with def.seed.
/// Throws Error on a bad definition or when no child can be started; a child that fails or
/// crashes gives an unsolved result whose status says why.
OmplRunResult runOmplForked(const Scenario& scenario, const FootprintChecker& checker,
                            const OmplRunDef& def);

/// "time=Ss": what ends an OMPL run.
std::string budgetName(const OmplRunDef& def);

/// runOmplForked, then parksim's exact check of the dense path, as a bench.csv row. The path is
/// interpolated at check.max_step_m (def.dense_step_m is replaced by it).
BenchRecord runOmpl(const Scenario& scenario, const BulletCollisionWorld& world,
                    const OmplRunDef& def, const PathCheckDef& check = {});

}  // namespace parksim::bench
