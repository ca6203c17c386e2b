#include "parksim/planner/tree/ShortcutSmoother.h"

#include <map>
#include <optional>
#include <utility>

namespace parksim {

namespace {

// A segment of the plan being smoothed, with what is known about it.
struct Piece {
  PathSegment segment;
  MotionSummary motion;
  enum class Check { kUnknown, kValid, kInvalid } check = Check::kUnknown;
};

// Below this a cost difference is rounding, not an improvement, m.
constexpr double kCostEpsilonM = 1e-9;

}  // namespace

ShortcutSmoother::ShortcutSmoother(const RobotDef& robot, const SteeringFunction& steering,
                                   const MotionValidator& validator, const CostWeights& weights)
    : robot_(robot), steering_(steering), validator_(validator), weights_(weights) {}

std::vector<PathSegment> ShortcutSmoother::smooth(std::vector<PathSegment> segments,
                                                  const Pose2& goal, int attempts,
                                                  std::mt19937_64& rng,
                                                  SmoothingStats* stats) const {
  SmoothingStats local;
  SmoothingStats& st = stats ? *stats : local;
  // The plan: pieces[k] runs from waypoint k to waypoint k + 1; ids[k] names waypoint k by its
  // index in the input, so segments re-steered between the same two waypoints can be reused.
  std::vector<Piece> pieces;
  std::vector<Pose2> waypoints;
  std::vector<int> ids;
  for (PathSegment& s : segments) {
    if (s.trajectory.points.size() < 2) continue;  // does not move
    waypoints.push_back(s.trajectory.points.front().pose);
    ids.push_back(static_cast<int>(ids.size()));
    const MotionSummary m = summarizeMotion(s.trajectory, robot_);
    pieces.push_back({std::move(s), m, Piece::Check::kValid});  // validated by the planner
  }
  waypoints.push_back(goal);
  ids.push_back(static_cast<int>(ids.size()));

  auto cost = [&](const std::vector<const Piece*>& plan) {
    double c = 0.0;
    int last = 0;
    for (const Piece* p : plan) {
      c += motionCost(p->motion, weights_) +
           weights_.cusp_penalty_m * junctionCusps(last, p->motion.first_direction);
      last = lastDirectionAfter(last, p->motion);
    }
    return c;
  };
  auto makePiece = [&](SteerResult r, bool from_rest) -> std::optional<Piece> {
    if (!r.reached || r.trajectory.points.size() < 2) return std::nullopt;
    const MotionSummary m = summarizeMotion(r.trajectory, robot_);
    return Piece{{std::move(r.trajectory), from_rest}, m};
  };
  auto modeTo = [&](std::size_t b) {
    return b + 1 == waypoints.size() ? SteerMode::kToGoal : SteerMode::kExact;
  };
  // Segments steered from rest between two waypoints depend on nothing else: remember them,
  // and whether they are valid, across attempts.
  std::map<std::pair<int, int>, std::optional<Piece>> from_rest_cache;
  auto steerFromRest = [&](std::size_t a, std::size_t b) -> std::optional<Piece>& {
    auto [it, inserted] = from_rest_cache.try_emplace({ids[a], ids[b]});
    if (inserted)
      it->second = makePiece(steering_.steer(waypoints[a], {}, waypoints[b], modeTo(b)), true);
    return it->second;
  };
  auto validate = [&](Piece& p) {
    if (p.check == Piece::Check::kUnknown) {
      ++st.validated;
      p.check =
          validator_.isValid(p.segment.trajectory) ? Piece::Check::kValid : Piece::Check::kInvalid;
    }
    return p.check == Piece::Check::kValid;
  };

  std::vector<const Piece*> plan;
  for (const Piece& p : pieces) plan.push_back(&p);
  double current = cost(plan);
  for (int attempt = 0; attempt < attempts && pieces.size() >= 2; ++attempt) {
    ++st.attempts;
    const std::size_t n = pieces.size();  // waypoints 0..n; n is the goal
    const auto i = std::uniform_int_distribution<std::size_t>(0, n - 2)(rng);
    const auto j = std::uniform_int_distribution<std::size_t>(i + 2, n)(rng);
    // The shortcut starts with the wheel speeds the robot arrives at waypoint i with; from rest
    // (and so reusable) when the segment before ends with a legal stop.
    const bool at_rest = i == 0 || endsWithLegalStop(pieces[i - 1].segment.trajectory, robot_);
    std::optional<Piece> fresh;
    if (!at_rest) {
      const WheelSpeeds arrival = arrivalWheels(pieces[i - 1].segment.trajectory);
      fresh = makePiece(steering_.steer(waypoints[i], arrival, waypoints[j], modeTo(j)), false);
    }
    std::optional<Piece>& shortcut = at_rest ? steerFromRest(i, j) : fresh;
    if (!shortcut || shortcut->check == Piece::Check::kInvalid) continue;

    // The candidate: unchanged head, the shortcut, then the tail, re-steered from rest where a
    // segment was steered from its predecessor's arrival speeds, which have changed.
    std::vector<Piece*> candidate;
    for (std::size_t k = 0; k < i; ++k) candidate.push_back(&pieces[k]);
    candidate.push_back(&*shortcut);
    bool predecessor_changed = true;
    for (std::size_t k = j; k < n; ++k) {
      if (!predecessor_changed || pieces[k].segment.from_rest) {
        candidate.push_back(&pieces[k]);
        predecessor_changed = false;
        continue;
      }
      std::optional<Piece>& again = steerFromRest(k, k + 1);
      if (!again || again->check == Piece::Check::kInvalid) break;
      candidate.push_back(&*again);
    }
    if (candidate.size() != i + 1 + (n - j)) continue;  // a re-steered segment failed
    const double c = cost({candidate.begin(), candidate.end()});
    if (!(c < current - kCostEpsilonM)) continue;
    // Cheaper: check what is new (cached answers make repeated candidates cheap).
    bool valid = true;
    for (std::size_t k = i; k < candidate.size() && valid; ++k) valid = validate(*candidate[k]);
    if (!valid) continue;

    std::vector<Piece> next;
    next.reserve(candidate.size());
    for (Piece* p : candidate) next.push_back(*p);
    pieces = std::move(next);
    waypoints.erase(waypoints.begin() + static_cast<std::ptrdiff_t>(i + 1),
                    waypoints.begin() + static_cast<std::ptrdiff_t>(j));
    ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(i + 1),
              ids.begin() + static_cast<std::ptrdiff_t>(j));
    current = c;
    ++st.accepted;
  }

  std::vector<PathSegment> out;
  for (Piece& p : pieces) out.push_back(std::move(p.segment));
  return out;
}

}  // namespace parksim
