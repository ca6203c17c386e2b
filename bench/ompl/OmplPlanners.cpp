#include "bench/ompl/OmplPlanners.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <type_traits>

#include <ompl/base/PlannerData.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "bench/planning/ParksimRuns.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/Geometry.h"

namespace parksim::bench {

namespace ob = ompl::base;
namespace og = ompl::geometric;

const char* toString(OmplPlanner planner) {
  switch (planner) {
    case OmplPlanner::kRrt: return "RRT";
    case OmplPlanner::kRrtConnect: return "RRTConnect";
    case OmplPlanner::kRrtStar: return "RRTstar";
  }
  return "?";
}

const char* toString(OmplSpace space) {
  switch (space) {
    case OmplSpace::kReedsShepp: return "reeds-shepp";
    case OmplSpace::kSe2: return "se2";
  }
  return "?";
}

std::vector<OmplPlanner> allOmplPlanners() {
  return {OmplPlanner::kRrt, OmplPlanner::kRrtConnect, OmplPlanner::kRrtStar};
}

std::vector<OmplSpace> allOmplSpaces() { return {OmplSpace::kReedsShepp, OmplSpace::kSe2}; }

OmplPlanner omplPlannerFromString(const std::string& name) {
  for (OmplPlanner p : allOmplPlanners()) {
    if (name == toString(p)) return p;
  }
  throw Error("unknown OMPL planner '" + name + "' (expected RRT, RRTConnect or RRTstar)");
}

OmplSpace omplSpaceFromString(const std::string& name) {
  for (OmplSpace s : allOmplSpaces()) {
    if (name == toString(s)) return s;
  }
  throw Error("unknown OMPL state space '" + name + "' (expected reeds-shepp or se2)");
}

std::string budgetName(const OmplRunDef& def) {
  return "time=" + formatGeneral(def.time_limit_s) + "s";
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The footprint checker behind OMPL's validity interface: reference point inside the lot,
// grown footprint free.
class FootprintValidity final : public ob::StateValidityChecker {
 public:
  FootprintValidity(const ob::SpaceInformationPtr& si, const FootprintChecker& checker,
                    const LotBounds& lot, double margin_m)
      : ob::StateValidityChecker(si), checker_(checker), lot_(lot), margin_m_(margin_m) {}

  bool isValid(const ob::State* state) const override {
    const auto* s = state->as<ob::SE2StateSpace::StateType>();
    if (!lot_.contains(s->getX(), s->getY())) return false;
    return checker_.isFree({s->getX(), s->getY(), s->getYaw()}, margin_m_);
  }

 private:
  const FootprintChecker& checker_;
  LotBounds lot_;
  double margin_m_;
};

Pose2 toPose(const ob::State* state) {
  const auto* s = state->as<ob::SE2StateSpace::StateType>();
  return {s->getX(), s->getY(), s->getYaw()};
}

ob::PlannerPtr makePlanner(OmplPlanner planner, const ob::SpaceInformationPtr& si) {
  switch (planner) {
    case OmplPlanner::kRrt: return std::make_shared<og::RRT>(si);
    case OmplPlanner::kRrtConnect: return std::make_shared<og::RRTConnect>(si);
    case OmplPlanner::kRrtStar: return std::make_shared<og::RRTstar>(si);
  }
  throw Error("unknown OMPL planner");
}

// Interpolates the solution along the space's own curves (the curves OMPL's motion validator
// checked) so that footprint points move at most def.dense_step_m between two poses.
std::vector<Pose2> densePath(const og::PathGeometric& path, const ob::SpaceInformationPtr& si,
                             const OmplRunDef& def, double footprint_radius_m) {
  std::vector<Pose2> dense;
  const ob::StateSpacePtr& space = si->getStateSpace();
  auto* rs = dynamic_cast<ob::ReedsSheppStateSpace*>(space.get());
  ob::State* tmp = si->allocState();
  for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i) {
    const ob::State* a = path.getState(i);
    const ob::State* b = path.getState(i + 1);
    double bound;
    if (rs != nullptr) {
      // Reeds-Shepp interpolation is linear in arc length L, and the heading turns at most
      // 1/rho per metre of arc: a point at distance r moves at most L (1 + r / rho).
      bound = si->distance(a, b) * (1.0 + footprint_radius_m / def.turning_radius_m);
    } else {
      // SE2 interpolation is linear in x, y and the shortest heading change.
      bound = footprintStep(toPose(a), toPose(b), footprint_radius_m);
    }
    const int n = std::max(1, static_cast<int>(std::ceil(bound / def.dense_step_m)));
    bool first_time = true;
    ob::ReedsSheppStateSpace::ReedsSheppPath rs_path;
    for (int k = 0; k < n; ++k) {
      const double t = static_cast<double>(k) / n;
      if (k == 0) {
        dense.push_back(toPose(a));
      } else if (rs != nullptr) {
        rs->interpolate(a, b, t, first_time, rs_path, tmp);
        dense.push_back(toPose(tmp));
      } else {
        space->interpolate(a, b, t, tmp);
        dense.push_back(toPose(tmp));
      }
    }
  }
  if (path.getStateCount() > 0) dense.push_back(toPose(path.getState(path.getStateCount() - 1)));
  si->freeState(tmp);
  return dense;
}

// One run, in the calling process. Only ever called in a freshly forked child: it sets OMPL's
// process-wide seed and log level.
OmplRunResult runInThisProcess(const Scenario& scenario, const FootprintChecker& checker,
                               const OmplRunDef& def) {
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(def.seed);

  std::shared_ptr<ob::SE2StateSpace> space;
  if (def.space == OmplSpace::kReedsShepp) {
    space = std::make_shared<ob::ReedsSheppStateSpace>(def.turning_radius_m);
  } else {
    space = std::make_shared<ob::SE2StateSpace>();
  }
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, scenario.lot.x_min_m);
  bounds.setHigh(0, scenario.lot.x_max_m);
  bounds.setLow(1, scenario.lot.y_min_m);
  bounds.setHigh(1, scenario.lot.y_max_m);
  space->setBounds(bounds);

  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(
      std::make_shared<FootprintValidity>(si, checker, scenario.lot, def.margin_m));
  if (def.space == OmplSpace::kReedsShepp) {
    si->setMotionValidator(std::make_shared<ob::ReedsSheppMotionValidator>(si));
  }
  si->setStateValidityCheckingResolution(def.segment_m / space->getMaximumExtent());
  si->setup();

  ob::ScopedState<ob::SE2StateSpace> start(space);
  ob::ScopedState<ob::SE2StateSpace> goal(space);
  start->setXY(scenario.start.x, scenario.start.y);
  start->setYaw(scenario.start.theta);
  goal->setXY(scenario.goal.pose.x, scenario.goal.pose.y);
  goal->setYaw(scenario.goal.pose.theta);
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(start, goal, def.goal_threshold);
  pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));

  OmplRunResult result;
  Clock::time_point t0;
  // RRT* keeps going after its first solution and reports it only through this callback.
  pdef->setIntermediateSolutionCallback(
      [&](const ob::Planner*, const std::vector<const ob::State*>&, const ob::Cost&) {
        if (std::isnan(result.time_first_s)) result.time_first_s = secondsSince(t0);
      });

  ob::PlannerPtr planner = makePlanner(def.planner, si);
  planner->setProblemDefinition(pdef);
  planner->setup();

  const ob::PlannerTerminationCondition ptc =
      ob::timedPlannerTerminationCondition(def.time_limit_s);
  const double cpu0 = threadCpuSeconds();
  t0 = Clock::now();
  const ob::PlannerStatus status = planner->solve(ptc);
  result.time_total_s = secondsSince(t0);
  result.cpu_total_s = threadCpuSeconds() - cpu0;

  result.status = status.asString();
  result.status_code = static_cast<int>(ob::PlannerStatus::StatusType(status));
  result.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
  if (result.solved) {
    // RRT and RRTConnect return at their first solution.
    if (std::isnan(result.time_first_s)) result.time_first_s = result.time_total_s;
    const auto& path = *pdef->getSolutionPath()->as<og::PathGeometric>();
    result.ompl_length = path.length();
    for (std::size_t i = 0; i < path.getStateCount(); ++i) {
      result.waypoints.push_back(toPose(path.getState(i)));
    }
    result.dense = densePath(path, si, def, footprintRadius(scenario.robot));
  } else {
    result.time_first_s = kNotMeasured;
  }
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  result.graph_states = static_cast<long>(data.numVertices());
  return result;
}

// The result crosses the pipe as raw bytes: both ends are the same binary.
class Encoder {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put(const std::string& s) {
    put(s.size());
    bytes_ += s;
  }
  void put(const std::vector<Pose2>& poses) {
    static_assert(std::is_trivially_copyable_v<Pose2>);
    put(poses.size());
    bytes_.append(reinterpret_cast<const char*>(poses.data()), poses.size() * sizeof(Pose2));
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Decoder {
 public:
  explicit Decoder(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  void get(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    take(&value, sizeof value);
  }
  void get(std::string& s) {
    std::size_t n = 0;
    get(n);
    need(n);
    s.assign(bytes_, pos_, n);
    pos_ += n;
  }
  void get(std::vector<Pose2>& poses) {
    std::size_t n = 0;
    get(n);
    need(n * sizeof(Pose2));
    poses.resize(n);
    take(poses.data(), n * sizeof(Pose2));
  }
  bool done() const { return pos_ == bytes_.size(); }

 private:
  void need(std::size_t n) const {
    if (bytes_.size() - pos_ < n) throw Error("OMPL child: truncated result");
  }
  void take(void* out, std::size_t n) {
    need(n);
    std::memcpy(out, bytes_.data() + pos_, n);
    pos_ += n;
  }
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

std::string encode(const OmplRunResult& r) {
  Encoder e;
  e.put(r.solved);
  e.put(r.status);
  e.put(r.status_code);
  e.put(r.time_first_s);
  e.put(r.time_total_s);
  e.put(r.cpu_total_s);
  e.put(r.ompl_length);
  e.put(r.graph_states);
  e.put(r.waypoints);
  e.put(r.dense);
  return e.bytes();
}

OmplRunResult decode(const std::string& bytes) {
  Decoder d(bytes);
  OmplRunResult r;
  d.get(r.solved);
  d.get(r.status);
  d.get(r.status_code);
  d.get(r.time_first_s);
  d.get(r.time_total_s);
  d.get(r.cpu_total_s);
  d.get(r.ompl_length);
  d.get(r.graph_states);
  d.get(r.waypoints);
  d.get(r.dense);
  if (!d.done()) throw Error("OMPL child: trailing bytes in result");
  return r;
}

bool writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string readAll(int fd) {
  std::string bytes;
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buf, static_cast<std::size_t>(n));
  }
  return bytes;
}

OmplRunResult failed(std::string why) {
  OmplRunResult r;
  r.status = std::move(why);
  r.status_code = static_cast<int>(ob::PlannerStatus::CRASH);
  return r;
}

}  // namespace

OmplRunResult runOmplForked(const Scenario& scenario, const FootprintChecker& checker,
                            const OmplRunDef& def) {
  if (def.seed == 0) throw Error("OMPL run: seed must be > 0 (OMPL ignores seed 0)");
  if (!(def.time_limit_s > 0.0) || !(def.turning_radius_m > 0.0) || !(def.segment_m > 0.0) ||
      !(def.margin_m >= 0.0) || !(def.goal_threshold > 0.0) || !(def.dense_step_m > 0.0)) {
    throw Error(
        "OMPL run: time limit, turning radius, segment, goal threshold and dense step "
        "must be positive, the margin non-negative");
  }
  int fds[2];
  if (::pipe(fds) != 0) throw Error(std::string("OMPL run: pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(std::string("OMPL run: fork: ") + std::strerror(err));
  }
  if (pid == 0) {
    // Child: plan, send, and leave without running the parent's exit handlers or flushing
    // its copies of the parent's stdio buffers.
    ::close(fds[0]);
    std::string bytes;
    try {
      bytes = encode(runInThisProcess(scenario, checker, def));
    } catch (const std::exception& e) {
      bytes = encode(failed(std::string("child error: ") + e.what()));
    } catch (...) {
      bytes = encode(failed("child error"));
    }
    const bool sent = writeAll(fds[1], bytes);
    ::close(fds[1]);
    ::_exit(sent ? 0 : 1);
  }
  ::close(fds[1]);
  const std::string bytes = readAll(fds[0]);
  ::close(fds[0]);
  int wstatus = 0;
  while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(wstatus)) {
    return failed("child killed by signal " + std::to_string(WTERMSIG(wstatus)));
  }
  if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) {
    return failed("child exited with status " + std::to_string(WEXITSTATUS(wstatus)));
  }
  return decode(bytes);
}

BenchRecord runOmpl(const Scenario& scenario, const BulletCollisionWorld& world,
                    const OmplRunDef& def, const PathCheckDef& check) {
  OmplRunDef dense_def = def;
  dense_def.dense_step_m = check.max_step_m;
  const OmplRunResult run = runOmplForked(scenario, world, dense_def);
  BenchRecord r;
  r.library = "ompl";
  r.planner = toString(def.planner);
  r.space = toString(def.space);
  r.scenario = scenario.name;
  r.seed = def.seed;
  r.budget = budgetName(def);
  r.solved = run.solved;
  r.status = run.status;
  r.time_first_s = run.time_first_s;
  r.time_total_s = run.time_total_s;
  r.cpu_total_s = run.cpu_total_s;
  r.tree_size = run.graph_states;
  if (run.solved) {
    const PathCheck verdict = checkPath(run.dense, scenario, world, check);
    r.valid = verdict.valid;
    r.length_m = verdict.length_m;
    r.min_clearance_m = verdict.min_clearance_m;
    r.cusps = countCusps(run.dense);
  }
  return r;
}

}  // namespace parksim::bench
