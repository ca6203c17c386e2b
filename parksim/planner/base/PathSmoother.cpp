#include "parksim/planner/base/PathSmoother.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/planner/motion/CarPlanAlong.h"
#include "parksim/planner/motion/CarTimeCost.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/motion/TimeCost.h"
#include "parksim/planner/steering/BalkcomMason.h"

namespace parksim {

namespace {

// A candidate must be faster by more than this to be kept, s.
constexpr double kImprovementS = 1e-9;
// The bisection pass starts shortcuts from about this many junctions at most, on the path
// split into parts of about this length (m), and runs at most this many times.
constexpr std::size_t kBisectionStarts = 48;
constexpr double kDensifyM = 0.05;
constexpr int kBisectionPasses = 3;
// Pieces that turn or drive less than this are not corners' parts, m or rad.
constexpr double kTinyMotion = 1e-9;

// The motion of a piece as a twist held for 1 s: v is the distance (m), omega the turn (rad).
Twist motionOf(const PathPiece& p, const RobotDef& robot) {
  return toTwist({p.direction.left_radps * p.travel_rad, p.direction.right_radps * p.travel_rad},
                 robot);
}

PathPiece pieceOfMotion(const Twist& motion, const RobotDef& robot) {
  return pieceOf(toWheelSpeeds(motion, robot), 1.0);
}

// The path being smoothed: its pieces and the pose where each starts (and the end pose).
class Path {
 public:
  Path(const Pose2& start, std::vector<PathPiece> pieces, const RobotDef& robot)
      : robot_(robot), start_(start) {
    for (const PathPiece& p : pieces) appendPiece(pieces_, p);
    update();
  }

  const std::vector<PathPiece>& pieces() const { return pieces_; }
  const Pose2& pose(std::size_t junction) const { return poses_[junction]; }
  std::size_t size() const { return pieces_.size(); }
  double travel() const { return total_travel_; }

  // Pieces [0, i) then `middle` then pieces [j, end).
  std::vector<PathPiece> spliced(std::size_t i, const std::vector<PathPiece>& middle,
                                 std::size_t j) const {
    std::vector<PathPiece> out;
    for (std::size_t k = 0; k < i; ++k) appendPiece(out, pieces_[k]);
    for (const PathPiece& p : middle) appendPiece(out, p);
    for (std::size_t k = j; k < pieces_.size(); ++k) appendPiece(out, pieces_[k]);
    return out;
  }

  // Splits the piece holding the path position `at` (a travel from the start) so that a
  // junction lies there; returns that junction's index.
  std::size_t splitAt(double at) {
    double before = 0.0;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      const double t = pieces_[i].travel_rad;
      if (at < before + t) {
        const double head = at - before;
        if (head <= kTinyMotion) return i;
        if (t - head <= kTinyMotion) return i + 1;
        PathPiece tail = pieces_[i];
        tail.travel_rad = t - head;
        pieces_[i].travel_rad = head;
        pieces_.insert(pieces_.begin() + static_cast<std::ptrdiff_t>(i) + 1, tail);
        update();
        return i + 1;
      }
      before += t;
    }
    return pieces_.size();
  }

  // The junction at the path position `at` (after splitAt(at)).
  std::size_t junctionAt(double at) const {
    double before = 0.0;
    std::size_t j = 0;
    while (j < pieces_.size() && before + pieces_[j].travel_rad <= at + kTinyMotion) {
      before += pieces_[j].travel_rad;
      ++j;
    }
    return j;
  }

  // Splits every piece into equal parts whose faster wheel turns at most `travel_rad`, so that
  // shortcuts may start and end along long pieces too. Times exactly as before.
  void densify(double travel_rad) {
    std::vector<PathPiece> out;
    for (const PathPiece& p : pieces_) {
      const int n = std::max(1, static_cast<int>(std::ceil(p.travel_rad / travel_rad)));
      for (int k = 0; k < n; ++k) out.push_back({p.direction, p.travel_rad / n});
    }
    pieces_ = std::move(out);
    update();
  }

  void replace(std::vector<PathPiece> pieces) {
    pieces_ = std::move(pieces);
    update();
  }

  // Joins consecutive pieces of one direction again.
  void join() {
    std::vector<PathPiece> joined;
    for (const PathPiece& p : pieces_) appendPiece(joined, p);
    replace(std::move(joined));
  }

 private:
  void update() {
    poses_.assign(1, start_);
    total_travel_ = 0.0;
    for (const PathPiece& p : pieces_) {
      poses_.push_back(integrateExact(poses_.back(), motionOf(p, robot_), 1.0));
      total_travel_ += p.travel_rad;
    }
  }

  RobotDef robot_;
  Pose2 start_;
  std::vector<PathPiece> pieces_;
  std::vector<Pose2> poses_;
  double total_travel_ = 0.0;
};

// One smoothing run: the path, its duration, and the checks made.
class Run {
 public:
  Run(const PathSmoother& smoother, const RobotDef& robot, const MotionValidator& validator,
      const TimingLimits& limits, const Pose2& start, std::vector<PathPiece> pieces,
      PathSmoothingStats& stats)
      : smoother_(smoother),
        robot_(robot),
        validator_(validator),
        limits_(limits),
        path_(start, std::move(pieces), robot),
        stats_(stats) {
    duration_ = smoother_.duration(path_.pieces());
    stats_.before_s = duration_;
  }

  // Replaces junctions i..j by the fastest valid free-space connection that makes the plan
  // faster, if any. Candidates are ranked by the change of the O(1)-per-piece estimate over the
  // stretch they replace (TimeCost.h); those it says are faster are checked, and the first
  // valid one that the exact timing confirms is kept.
  bool tryShortcut(std::size_t i, std::size_t j) {
    const std::vector<PathPiece>& pieces = path_.pieces();
    const WheelSpeeds before = i > 0 ? pieces[i - 1].direction : WheelSpeeds{};
    const WheelSpeeds after = j < pieces.size() ? pieces[j].direction : WheelSpeeds{};
    const double old_estimate =
        smoother_.stretchTime(before,
                              {pieces.begin() + static_cast<std::ptrdiff_t>(i),
                               pieces.begin() + static_cast<std::ptrdiff_t>(j)},
                              after);
    struct Candidate {
      double gain;
      std::vector<PathPiece> middle;
    };
    std::vector<Candidate> candidates;
    for (std::vector<PathPiece>& middle : smoother_.connections(path_.pose(i), path_.pose(j))) {
      const double gain = old_estimate - smoother_.stretchTime(before, middle, after);
      if (gain > kImprovementS) candidates.push_back({gain, std::move(middle)});
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.gain > b.gain; });
    for (Candidate& c : candidates) {
      ++stats_.validated;
      if (!validator_.isValid(geometryOf(path_.pose(i), c.middle, robot_))) continue;
      std::vector<PathPiece> candidate = path_.spliced(i, c.middle, j);
      const double d = smoother_.duration(candidate);
      if (!(d < duration_ - kImprovementS)) continue;
      path_.replace(std::move(candidate));
      duration_ = d;
      ++stats_.shortcuts;
      return true;
    }
    return false;
  }

  // From each junction in turn, the farthest shortcut among junctions at halving distances,
  // on the path split into parts of about kDensifyM (so that shortcuts may leave from and land
  // on long pieces), until a pass keeps none. On paths of many pieces only about
  // kBisectionStarts evenly spread junctions start shortcuts, bounding a pass.
  void bisectionShortcuts() {
    for (int pass = 0; pass < kBisectionPasses; ++pass) {
      path_.densify(kDensifyM / robot_.wheel_radius_m);
      const int before = stats_.shortcuts;
      const std::size_t stride = std::max<std::size_t>(1, path_.size() / kBisectionStarts);
      for (std::size_t i = 0; i + 1 < path_.size(); i += stride) {
        for (std::size_t gap = path_.size() - i; gap >= 2; gap /= 2) {
          if (tryShortcut(i, i + gap)) break;
        }
      }
      path_.join();
      if (stats_.shortcuts == before) break;
    }
  }

  // Shortcuts between random poses along the path, anywhere on its pieces.
  void randomShortcuts(int attempts, std::mt19937_64& rng) {
    for (int a = 0; a < attempts && !path_.pieces().empty(); ++a) {
      std::uniform_real_distribution<double> along(0.0, path_.travel());
      double u = along(rng);
      double w = along(rng);
      if (u > w) std::swap(u, w);
      // A split path times exactly as before (pieces of one direction join again when timed),
      // but is put back unless the shortcut is kept.
      Path saved = path_;
      path_.splitAt(w);
      const std::size_t i = path_.splitAt(u);
      const std::size_t j = path_.junctionAt(w);
      if (j <= i || !tryShortcut(i, j)) path_ = std::move(saved);
    }
  }

  // Each turn in place between two straight drives in one direction becomes an arc tangent to
  // both, of the largest radius that is valid and faster.
  void fillets(const std::vector<double>& radii) {
    for (std::size_t i = 1; i + 1 < path_.size(); ++i) {
      const Twist a = motionOf(path_.pieces()[i - 1], robot_);
      const Twist turn = motionOf(path_.pieces()[i], robot_);
      const Twist b = motionOf(path_.pieces()[i + 1], robot_);
      const bool corner = std::abs(turn.v_mps) <= kTinyMotion &&
                          std::abs(turn.omega_radps) > kTinyMotion &&
                          std::abs(a.omega_radps) <= kTinyMotion &&
                          std::abs(b.omega_radps) <= kTinyMotion && a.v_mps * b.v_mps > 0.0;
      if (!corner) continue;
      const double angle = turn.omega_radps;
      const double sign = a.v_mps > 0.0 ? 1.0 : -1.0;
      for (double r : radii) {
        const double cut = r * std::tan(0.5 * std::abs(angle));
        if (!(cut < std::abs(a.v_mps)) || !(cut < std::abs(b.v_mps))) continue;
        const std::vector<PathPiece> middle{
            pieceOfMotion({a.v_mps - sign * cut, 0.0}, robot_),
            pieceOfMotion({sign * r * std::abs(angle), angle}, robot_),
            pieceOfMotion({b.v_mps - sign * cut, 0.0}, robot_)};
        std::vector<PathPiece> candidate = path_.spliced(i - 1, middle, i + 2);
        const double d = smoother_.duration(candidate);
        if (!(d < duration_ - kImprovementS)) continue;
        ++stats_.validated;
        const Pose2 arc_start = integrateExact(path_.pose(i - 1), motionOf(middle[0], robot_), 1.0);
        if (!validator_.isValid(geometryOf(arc_start, {middle[1]}, robot_))) continue;
        path_.replace(std::move(candidate));
        duration_ = d;
        ++stats_.fillets;
        break;
      }
    }
  }

  std::vector<PathPiece> result() {
    stats_.after_s = duration_;
    return path_.pieces();
  }

 private:
  const PathSmoother& smoother_;
  RobotDef robot_;
  const MotionValidator& validator_;
  TimingLimits limits_;
  Path path_;
  PathSmoothingStats& stats_;
  double duration_ = 0.0;  // exact, as timed
};

}  // namespace

PathSmoother::PathSmoother(const RobotDef& robot, const MotionValidator& validator,
                           const TimingLimits& limits, const PathSmootherDef& def)
    : robot_(robot), validator_(validator), limits_(limits), def_(def) {
  for (double r : def.fillet_radii_m) {
    if (!(r > 0.0)) throw Error("path smoother: fillet radii must be positive");
  }
  for (double r : def.curve_radii_m) {
    if (!(r > 0.0)) throw Error("path smoother: curve radii must be positive");
    ReedsSheppDef rs;
    rs.turning_radius_m = r;
    curves_.push_back(std::make_unique<ReedsSheppSteering>(robot, rs));
  }
}

PathSmoother::PathSmoother(const CarLimits& limits, const RobotDef& car,
                           const MotionValidator& validator, const PathSmootherDef& def)
    : robot_(car), validator_(validator), def_(def), car_(limits) {
  if (!car.isCar()) throw Error("path smoother: car limits for a robot that is not a car");
  for (double m : def.car_curve_radii) {
    if (!(m >= 1.0)) throw Error("path smoother: a car's curve radii must be >= 1 (multiples)");
    ReedsSheppDef rs;
    rs.turning_radius_m = m * car.minTurningRadius();
    curves_.push_back(std::make_unique<ReedsSheppSteering>(car, rs));
  }
}

PathSmoother::~PathSmoother() = default;

double PathSmoother::duration(const std::vector<PathPiece>& pieces) const {
  return car_ ? carPlanDuration(pieces, robot_, *car_) : timedDuration(pieces, limits_);
}

namespace {

// A car's driving direction (0: at rest) and curvature along a piece, and its length, m.
struct CarMotion {
  int direction = 0;
  double kappa = 0.0;
  double length = 0.0;
};

CarMotion carMotionOf(const WheelSpeeds& w, double travel, const RobotDef& car) {
  const Twist t = toTwist(w, car);
  if (!(std::abs(t.v_mps) > kTinyMotion)) return {};
  return {t.v_mps > 0.0 ? 1 : -1, t.omega_radps / t.v_mps, std::abs(t.v_mps) * travel};
}

}  // namespace

double PathSmoother::stretchTime(const WheelSpeeds& before, const std::vector<PathPiece>& stretch,
                                 const WheelSpeeds& after) const {
  if (!car_) {
    const TimeCostModel cost(limits_);
    double t = 0.0;
    WheelSpeeds last = before;
    for (const PathPiece& p : stretch) {
      t += cost.pieceTime(p) + cost.junctionTime(last, p.direction);
      last = p.direction;
    }
    return t + cost.junctionTime(last, after);
  }
  const CarTimeCost cost(robot_, *car_);
  double t = 0.0;
  CarMotion last = carMotionOf(before, 1.0, robot_);
  double room = std::numeric_limits<double>::infinity();
  for (const PathPiece& p : stretch) {
    const CarMotion m = carMotionOf(p.direction, p.travel_rad, robot_);
    if (m.direction == 0) continue;
    room = std::min(room, 0.5 * m.length);
    t += cost.pieceTime(m.length, m.kappa) +
         cost.junctionTime(last.direction, last.kappa, m.direction, m.kappa, room);
    last = m;
    room = 0.5 * m.length;
  }
  const CarMotion end = carMotionOf(after, 1.0, robot_);
  return t + cost.junctionTime(last.direction, last.kappa, end.direction, end.kappa, room);
}

std::vector<std::vector<PathPiece>> PathSmoother::connections(const Pose2& from,
                                                              const Pose2& to) const {
  std::vector<std::vector<PathPiece>> out;
  if (!car_) out.push_back(piecesOf(balkcomMasonPath(from, to, 0.5 * robot_.wheel_base_m), robot_));
  for (const auto& curve : curves_) out.push_back(curve->pieces(from, to));
  return out;
}

std::vector<PathPiece> PathSmoother::smooth(const Pose2& start, std::vector<PathPiece> pieces,
                                            int random_shortcuts, std::mt19937_64& rng,
                                            PathSmoothingStats* stats) const {
  if (random_shortcuts < 0) throw Error("path smoother: random shortcuts must be >= 0");
  PathSmoothingStats local;
  Run run(*this, robot_, validator_, limits_, start, std::move(pieces), stats ? *stats : local);
  run.bisectionShortcuts();
  run.randomShortcuts(random_shortcuts, rng);
  run.fillets(def_.fillet_radii_m);
  return run.result();
}

}  // namespace parksim
