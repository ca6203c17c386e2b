// A plugin whose planners and controllers fail in every way user code does, for the tests of
// loading (PluginLoaderTest.cpp), of user code as a verdict (tests/pipeline/UserCodeTest.cpp,
// tests/sweep) and of the check that makes a component to check its parameters
// (tests/pipeline/ComponentCheckTest.cpp): each component is named for its fault.

#include <cmath>
#include <csignal>
#include <limits>
#include <stdexcept>

#include "parksim/sim/control/TrackingController.h"
#include "parksim/usercode/PluginApi.h"

namespace {

using namespace parksim;

struct NoDef {};
void noParams(NoDef&, ParamSet&) {}

// A controller's fault may be confined to the episodes that start beyond a point (a sweep with
// one faulty episode among many: tests/sweep/SweepUserCodeTest.cpp).
struct FaultDef {
  double start_x_above_m = -1e9;  ///< the fault strikes when the episode's start x exceeds this
};
void faultParams(FaultDef& d, ParamSet& s) {
  s.add("start_x_above_m", &d.start_x_above_m,
        "the fault strikes only when the episode starts at a larger x, m", -1e9, 1e9);
}

enum class Fault { kThrows, kNan, kThroughWalls, kTooFast, kSegfault, kHangs, kThrowsOnReset };

template <Fault F>
class FaultyPlanner : public Planner {
 public:
  explicit FaultyPlanner(const NoDef&) {}
  PlanResult solve(const PlanningProblem& p) override {
    PlanResult r;
    r.status = PlanStatus::kSolved;
    if constexpr (F == Fault::kThrows) throw std::runtime_error("no idea how to park");
    if constexpr (F == Fault::kSegfault) std::raise(SIGSEGV);
    if constexpr (F == Fault::kHangs) {
      for (volatile bool forever = true; forever;) {
      }
    }
    // Straight to the goal, through whatever is in the way; never validated.
    SteerResult s = p.steering.steer(p.scenario.start, {}, p.scenario.goal.pose, SteerMode::kExact);
    r.trajectory = std::move(s.trajectory);
    if constexpr (F == Fault::kNan) {
      r.trajectory.points[r.trajectory.points.size() / 2].pose.x =
          std::numeric_limits<double>::quiet_NaN();
    }
    if constexpr (F == Fault::kTooFast) {
      // The same path in half the time: every wheel speed doubled.
      for (TrajectoryPoint& q : r.trajectory.points) {
        q.t_s *= 0.5;
        q.wheels = {2.0 * q.wheels.left_radps, 2.0 * q.wheels.right_radps};
      }
    }
    return r;
  }
};

template <Fault F>
class FaultyController : public Controller {
 public:
  explicit FaultyController(const FaultDef& def) : def_(def), tracking_(TrackingDef{}) {}
  void reset(const ControllerSetup& setup) override {
    tracking_.reset(setup);
    limit_ = setup.scenario.robot.max_wheel_speed_radps;
    faulty_ = setup.scenario.start.x > def_.start_x_above_m;
    if constexpr (F == Fault::kThrowsOnReset) throw std::runtime_error("cannot read the plan");
  }
  WheelSpeeds command(const ControllerInput& in) override {
    // parksim's tracking for the first second, then the fault.
    if (in.t_s < 1.0 || !faulty_) return tracking_.command(in);
    if constexpr (F == Fault::kThrows) throw std::runtime_error("lost track");
    if constexpr (F == Fault::kNan) return {std::numeric_limits<double>::quiet_NaN(), 0.0};
    if constexpr (F == Fault::kTooFast) return {2.0 * limit_, 2.0 * limit_};
    if constexpr (F == Fault::kSegfault) std::raise(SIGSEGV);
    if constexpr (F == Fault::kHangs) {
      for (volatile bool forever = true; forever;) {
      }
    }
    return tracking_.command(in);
  }

 private:
  FaultDef def_;
  TrackingController tracking_;
  double limit_ = 0.0;
  bool faulty_ = true;
};

// A constructor that crashes or hangs when `value` exceeds `fault_above` (always, by default): a
// sweep may give values on both sides, in entries, set: lists or samples.
struct CtorDef {
  double value = 0.0;         ///< of no other use
  double fault_above = -1.0;  ///< the constructor crashes or hangs when value exceeds this
};
void ctorParams(CtorDef& d, ParamSet& s) {
  s.add("value", &d.value, "of no other use", -1e9, 1e9);
  s.add("fault_above", &d.fault_above, "the constructor crashes or hangs when value exceeds this",
        -1e9, 1e9);
}

template <Fault F>
void constructorFault(const CtorDef& def) {
  if (!(def.value > def.fault_above)) return;
  if constexpr (F == Fault::kSegfault) std::raise(SIGSEGV);
  if constexpr (F == Fault::kHangs) {
    for (volatile bool forever = true; forever;) {
    }
  }
}

// Made, it plans as through-walls does: its fault is in its constructor alone.
template <Fault F>
class CtorFaultyPlanner : public FaultyPlanner<Fault::kThroughWalls> {
 public:
  explicit CtorFaultyPlanner(const CtorDef& def) : FaultyPlanner(NoDef{}) {
    constructorFault<F>(def);
  }
};

// Made, it drives as parksim's tracking controller does.
template <Fault F>
class CtorFaultyController : public TrackingController {
 public:
  explicit CtorFaultyController(const CtorDef& def) : TrackingController(TrackingDef{}) {
    constructorFault<F>(def);
  }
};

// An entry for P, made from a default D with the parameters `bind` declares.
template <class P, class D>
PlannerEntry plannerOf(const char* name, const char* description, void (*bind)(D&, ParamSet&)) {
  PlannerInfo info;
  info.name = name;
  info.description = description;
  return plannerEntry<P>(std::move(info), D{}, bind);
}

template <class C, class D>
ControllerEntry controllerOf(const char* name, const char* description,
                             void (*bind)(D&, ParamSet&)) {
  ControllerInfo info;
  info.name = name;
  info.description = description;
  return controllerEntry<C>(std::move(info), D{}, bind);
}

template <Fault F>
PlannerEntry planner(const char* name) {
  return plannerOf<FaultyPlanner<F>>(name, "fails on purpose", &noParams);
}

template <Fault F>
ControllerEntry controller(const char* name) {
  return controllerOf<FaultyController<F>>(name, "fails on purpose", &faultParams);
}

template <Fault F>
PlannerEntry ctorPlanner(const char* name) {
  return plannerOf<CtorFaultyPlanner<F>>(name, "fails on purpose as it is made", &ctorParams);
}

template <Fault F>
ControllerEntry ctorController(const char* name) {
  return controllerOf<CtorFaultyController<F>>(name, "fails on purpose as it is made", &ctorParams);
}

// parksim's tracking controller registered through the plugin API: the same commands as the
// built-in one, to the bit, for the tests and the plugin overhead benchmark.
void bindTracking(TrackingDef&, ParamSet&) {}

void registerFaults(PluginRegistrar& r) {
  ControllerInfo copy;
  copy.name = "tracking-copy";
  copy.description = "parksim's tracking controller, from a plugin";
  r.addController(
      controllerEntry<TrackingController>(std::move(copy), TrackingDef{}, &bindTracking));
  r.addPlanner(planner<Fault::kThrows>("throwing-planner"));
  r.addPlanner(planner<Fault::kNan>("nan-planner"));
  r.addPlanner(planner<Fault::kThroughWalls>("through-walls"));
  r.addPlanner(planner<Fault::kTooFast>("too-fast-planner"));
  r.addPlanner(planner<Fault::kSegfault>("segfault-planner"));
  r.addPlanner(planner<Fault::kHangs>("hanging-planner"));
  r.addController(controller<Fault::kThrows>("throwing-controller"));
  r.addController(controller<Fault::kThrowsOnReset>("throwing-reset"));
  r.addController(controller<Fault::kNan>("nan-controller"));
  r.addController(controller<Fault::kTooFast>("too-fast-controller"));
  r.addController(controller<Fault::kSegfault>("segfault-controller"));
  r.addController(controller<Fault::kHangs>("hanging-controller"));
  r.addPlanner(ctorPlanner<Fault::kSegfault>("segfault-ctor-planner"));
  r.addPlanner(ctorPlanner<Fault::kHangs>("hanging-ctor-planner"));
  r.addController(ctorController<Fault::kSegfault>("segfault-ctor-controller"));
  r.addController(ctorController<Fault::kHangs>("hanging-ctor-controller"));
}

}  // namespace

PARKSIM_PLUGIN("parksim-faults", "0.1", registerFaults)
