// The tree planner's four variants (TreePlanner.h) as registered Planners: one implementation,
// the variant as configuration (OMPL's InformedRRTstar is RRT* configured, not copied).

#include <memory>
#include <vector>

#include "parksim/planner/base/PlanFinishing.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/base/Planner.h"
#include "parksim/planner/base/PlannerRegistry.h"
#include "parksim/planner/tree/TreePlanner.h"

namespace parksim {

namespace {

class TreePlannerAdapter : public Planner {
 public:
  explicit TreePlannerAdapter(const TreePlannerDef& def) : def_(def) {}

  PlanResult solve(const PlanningProblem& p) override {
    const Scenario& s = p.scenario;
    TreePlannerDef def = def_;
    static_cast<SearchDef&>(def) = p.search();
    // With time-optimal timing, smoothing follows the plan's geometry (finishPlan below); with
    // the study's timing the tree planner smooths with its own steering.
    const bool time_optimal = p.setup.timing == TimingKind::kTimeOptimal;
    if (time_optimal) def.smooth = false;
    const TreePlanner planner(s.robot, s.lot, p.steering, p.validator, def);
    PlanResult result = planner.solve(s.start, s.goal, p.progress);
    if (result.solved()) finishPlan(p, time_optimal && p.search().smooth, result);
    return result;
  }

 private:
  TreePlannerDef def_;
};

void bind(TreePlannerDef& d, ParamSet& s) {
  s.add("goal_bias", &d.goal_bias, "probability of sampling a goal pose", 0.0, 1.0);
  s.add("connect_radius_m", &d.connect_radius_m,
        "rrt: SE(2) distance to the goal that triggers a to-goal try, m; 0: 0.1 m x robot size / "
        "85 mm",
        0.0, 1e6);
  s.add("heading_length_m", &d.heading_length_m,
        "length that turns heading into distance in the SE(2) metric, m; 0: footprint radius", 0.0,
        1e6);
  s.add("extend_distance_m", &d.extend_distance_m,
        "rrt-star, rrt-connect's goal tree: longest step toward a sample (SE(2)), m; 0: 0.15 m x "
        "robot size / 85 mm",
        0.0, 1e6);
  s.add("rewire_neighbours", &d.rewire_neighbours,
        "rrt-star: neighbours considered for rewiring; 0: ceil(e (1 + 1/3) ln n)", 0, 100000);
  s.add("rewire_radius_m", &d.rewire_radius_m,
        "rrt-star: rewire every node within this SE(2) distance instead, m; 0: k-nearest", 0.0,
        1e6);
  s.add("informed_sampling", &d.informed_sampling,
        "rrt-star, once solved: sample only where a cheaper path could pass");
}

PlannerEntry treeEntry(const char* name, TreeVariant variant, const char* description) {
  PlannerInfo info;
  info.name = name;
  info.description = description;
  info.uses_steering = true;
  info.anytime = variant == TreeVariant::kRrtStar;
  // A car's Reeds-Shepp edges reach fewer poses than a differential drive's: ten times the
  // iterations.
  info.default_budget = [](const Scenario& s) {
    return lotScaledBudget(s.robot.isCar() ? 20000 : 2000, s);
  };
  TreePlannerDef def;
  def.variant = variant;
  return plannerEntry<TreePlannerAdapter>(std::move(info), def, &bind);
}

}  // namespace

std::vector<PlannerEntry> treePlanners() {
  return {treeEntry("rrt", TreeVariant::kRrt,
                    "RRT (study 2(e)): fixed-horizon steering, to-goal tries near the goal"),
          treeEntry("rrt-goal-connect", TreeVariant::kRrtGoalConnect,
                    "RRT (study 2(f)): every new node tries a to-goal trajectory"),
          treeEntry("rrt-star", TreeVariant::kRrtStar,
                    "RRT*: rest-to-rest edges rewired; anytime, informed sampling"),
          treeEntry("rrt-connect", TreeVariant::kRrtConnect,
                    "RRT-Connect: a start tree and a goal tree grown toward each other")};
}

}  // namespace parksim
