#include "parksim/planner/search/FootprintFit.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"

namespace parksim {

FootprintFit::FootprintFit(const std::vector<Obstacle>& obstacles, const RobotDef& robot,
                           double margin_m, int headings)
    : robot_(robot), margin_m_(margin_m), headings_(headings) {
  if (!(margin_m >= 0.0) || headings < 1) {
    throw Error("footprint fit: margin must be >= 0 and headings >= 1");
  }
  reach_m_ = footprintRadius(robot) + std::sqrt(2.0) * margin_m;
  for (int h = 0; h < headings_; ++h) {
    footprints_.push_back(
        footprintAt(robot_, Pose2{0.0, 0.0, 2.0 * kPi * h / headings_}, margin_m_));
    footprint_axes_.push_back(axesOf(footprints_.back()));
  }
  bucket_m_ = 2.0 * reach_m_;
  for (const Obstacle& o : obstacles) {
    if (!blocksRobot(o, robot)) continue;
    if (o.shape == ObstacleShape::kCompound) {
      for (std::size_t p = 0; p < o.compound->parts.size(); ++p) {
        const Eigen::AlignedBox2d& b = o.compound->bounds[p];
        add({Obstacle{}, o.compound, p, b.min().x(), b.min().y(), b.max().x(), b.max().y(), {}});
      }
      continue;
    }
    double x0 = o.box.center.x();
    double y0 = o.box.center.y();
    double x1 = x0;
    double y1 = y0;
    for (const Eigen::Vector2d& c : outline(o, 8)) {
      x0 = std::min(x0, c.x());
      y0 = std::min(y0, c.y());
      x1 = std::max(x1, c.x());
      y1 = std::max(y1, c.y());
    }
    if (o.shape == ObstacleShape::kCircle) {
      x0 = o.box.center.x() - o.radius_m;
      y0 = o.box.center.y() - o.radius_m;
      x1 = o.box.center.x() + o.radius_m;
      y1 = o.box.center.y() + o.radius_m;
    }
    add({o, nullptr, 0, x0, y0, x1, y1, axesOf(o.box)});
  }
}

void FootprintFit::add(Shape shape) {
  const int id = static_cast<int>(shapes_.size());
  // Every bucket a reference point could be in while the footprint touches the shape.
  const auto i0 = static_cast<std::int64_t>(std::floor((shape.x_min - reach_m_) / bucket_m_));
  const auto i1 = static_cast<std::int64_t>(std::floor((shape.x_max + reach_m_) / bucket_m_));
  const auto j0 = static_cast<std::int64_t>(std::floor((shape.y_min - reach_m_) / bucket_m_));
  const auto j1 = static_cast<std::int64_t>(std::floor((shape.y_max + reach_m_) / bucket_m_));
  shapes_.push_back(std::move(shape));
  for (std::int64_t i = i0; i <= i1; ++i) {
    for (std::int64_t j = j0; j <= j1; ++j) buckets_[bucketKey(i, j)].push_back(id);
  }
}

double FootprintFit::separationOf(const OrientedBox& footprint, const BoxAxes& axes,
                                  const Shape& shape) const {
  if (shape.compound) {
    return separationAlongAxes(footprint, axes, shape.compound->parts[shape.part]);
  }
  if (shape.obstacle.shape == ObstacleShape::kBox) {
    return separationAlongAxes(footprint, axes, shape.obstacle.box, shape.axes);
  }
  if (shape.obstacle.shape == ObstacleShape::kPolygon) {
    return separationAlongAxes(footprint, axes, shape.obstacle.vertices);
  }
  return separation(footprint, shape.obstacle);
}

bool FootprintFit::fitsSomeHeading(double x, double y) const {
  const auto it = buckets_.find(bucketKey(static_cast<std::int64_t>(std::floor(x / bucket_m_)),
                                          static_cast<std::int64_t>(std::floor(y / bucket_m_))));
  if (it == buckets_.end()) return true;
  // Only obstacles within reach of the position can touch the footprint in any heading.
  auto near = [&](const Shape& s) {
    return x + reach_m_ > s.x_min && x - reach_m_ < s.x_max && y + reach_m_ > s.y_min &&
           y - reach_m_ < s.y_max;
  };
  if (std::none_of(it->second.begin(), it->second.end(),
                   [&](int id) { return near(shapes_[id]); })) {
    return true;
  }
  for (int h = 0; h < headings_; ++h) {
    // footprintAt(robot_, Pose2{x, y, heading}, margin_m_), to the last bit.
    OrientedBox fp = footprints_[h];
    fp.center = {x + fp.center.x(), y + fp.center.y()};
    bool free = true;
    for (int id : it->second) {
      if (near(shapes_[id]) && separationOf(fp, footprint_axes_[h], shapes_[id]) < 0.0) {
        free = false;
        break;
      }
    }
    if (free) return true;
  }
  return false;
}

}  // namespace parksim
