#include "parksim/scenario/world/FreePlace.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <tuple>
#include <vector>

namespace parksim {

namespace {

// Axis-aligned bounds of a box (the footprint at heading 0 is one).
Eigen::AlignedBox2d boundsOfBox(const OrientedBox& b) {
  Eigen::AlignedBox2d out;
  for (const Eigen::Vector2d& c : b.corners()) out.extend(c);
  return out;
}

// The larger of the gaps along x and along y between two bounds: a lower bound of the
// separating-axis separation of the shapes within them when the footprint is axis-aligned (x
// and y are then among its axes).
double axisGap(const Eigen::AlignedBox2d& a, const Eigen::AlignedBox2d& b) {
  const double gx = std::max(b.min().x() - a.max().x(), a.min().x() - b.max().x());
  const double gy = std::max(b.min().y() - a.max().y(), a.min().y() - b.max().y());
  return std::max(gx, gy);
}

struct Square {
  double key = 0.0;  // smaller first: the nearest corner's x + y, signed by the direction
  long seq = 0;      // insertion order: ties resolved the same way every time
  Eigen::Vector2d center;
  Eigen::Vector2d half;
  bool operator<(const Square& o) const {  // std::priority_queue pops the largest
    return std::tie(key, seq) > std::tie(o.key, o.seq);
  }
};

}  // namespace

double footprintClearance(const Scenario& s, const Pose2& pose) {
  const OrientedBox fp = footprintAt(s.robot, pose);
  const bool axis_aligned = pose.theta == 0.0;
  const Eigen::AlignedBox2d fb = boundsOfBox(fp);
  double best = std::numeric_limits<double>::infinity();
  for (const Obstacle& o : s.obstacles) {
    if (!blocksRobot(o, s.robot)) continue;
    if (o.shape != ObstacleShape::kCompound) {
      best = std::min(best, separation(fp, o));
      continue;
    }
    const CompoundShape& c = *o.compound;
    for (std::size_t i = 0; i < c.parts.size(); ++i) {
      if (axis_aligned && axisGap(fb, c.bounds[i]) >= best) continue;
      best = std::min(best, separationAlongAxes(fp, c.parts[i]));
    }
  }
  return best;
}

std::optional<Pose2> findFreePlace(const Scenario& s, const FreePlaceQuery& q) {
  const double room = q.room_m;
  const LotBounds& lot = s.lot;
  // Where placementProblem lets the reference point be.
  const Eigen::Vector2d lo(lot.x_min_m + room, lot.y_min_m + room);
  const Eigen::Vector2d hi(lot.x_max_m - room, lot.y_max_m - room);
  if (!(lo.x() <= hi.x() && lo.y() <= hi.y())) return std::nullopt;
  const Eigen::Vector2d size = hi - lo;
  const double smallest = std::max(room, 1e-6) * kFreePlaceResolution;
  // Near-square tiles to start from (at most 64 along the longer side).
  const double side = std::max({size.minCoeff(), size.maxCoeff() / 64.0, smallest});
  const int nx = std::max(1, static_cast<int>(std::ceil(size.x() / side)));
  const int ny = std::max(1, static_cast<int>(std::ceil(size.y() / side)));
  const double sign = q.from_upper_right ? -1.0 : 1.0;
  std::priority_queue<Square> open;
  long seq = 0;
  const auto push = [&](const Eigen::Vector2d& center, const Eigen::Vector2d& half) {
    const Eigen::Vector2d near = center - sign * half;
    open.push({sign * (near.x() + near.y()), seq++, center, half});
  };
  const Eigen::Vector2d tile_half(0.5 * size.x() / nx, 0.5 * size.y() / ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      push(lo + Eigen::Vector2d((2 * i + 1) * tile_half.x(), (2 * j + 1) * tile_half.y()),
           tile_half);
    }
  }
  for (int checks = 0; !open.empty() && checks < kMaxFreePlaceChecks; ++checks) {
    const Square sq = open.top();
    open.pop();
    const Pose2 p{sq.center.x(), sq.center.y(), 0.0};
    const double reach = sq.half.norm();
    // A free place keeps its footprint `room` from every obstacle: no point of this square
    // comes that far when its centre falls short by more than the square's half-diagonal.
    if (footprintClearance(s, p) + reach < room - 1e-9) continue;
    if (!placementProblem(s, p, room) && (!q.accept || q.accept(p))) return p;
    if (sq.half.maxCoeff() < smallest) continue;
    const Eigen::Vector2d h = 0.5 * sq.half;
    for (const Eigen::Vector2d& d : {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1),
                                     Eigen::Vector2d(-1, 1), Eigen::Vector2d(1, 1)}) {
      push(sq.center + d.cwiseProduct(h), h);
    }
  }
  return std::nullopt;
}

}  // namespace parksim
