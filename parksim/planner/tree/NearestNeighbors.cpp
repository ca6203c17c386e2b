#include "parksim/planner/tree/NearestNeighbors.h"

#include <algorithm>
#include <array>
#include <cmath>

// nanoflann 1.4.3 copies a not-yet-computed bounding box while building its sub-trees; the value
// is overwritten before use, but GCC's -Wmaybe-uninitialized flags it.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <nanoflann.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace parksim {

namespace {

using Point = std::array<double, 4>;

Point embed(const Pose2& p, double l) {
  return {p.x, p.y, l * std::cos(p.theta), l * std::sin(p.theta)};
}

struct PointCloud {
  std::vector<Point> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t idx, std::size_t dim) const { return points[idx][dim]; }
  template <class Bbox>
  bool kdtree_get_bbox(Bbox&) const {
    return false;
  }
};

using Tree =
    nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                               PointCloud, 4, std::size_t>;

}  // namespace

struct NearestNeighbors::Index {
  PointCloud cloud;
  // Sized for a million nodes; the dynamic adaptor keeps log2(capacity) sub-trees.
  Tree tree{4, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10), std::size_t{1} << 20};
};

NearestNeighbors::NearestNeighbors(double heading_length_m)
    : l_(heading_length_m), index_(std::make_unique<Index>()) {}

NearestNeighbors::~NearestNeighbors() = default;

std::size_t NearestNeighbors::add(const Pose2& pose) {
  const std::size_t idx = index_->cloud.points.size();
  index_->cloud.points.push_back(embed(pose, l_));
  index_->tree.addPoints(idx, idx);
  return idx;
}

std::size_t NearestNeighbors::size() const { return index_->cloud.points.size(); }

std::vector<std::size_t> NearestNeighbors::kNearest(const Pose2& query, std::size_t k) const {
  k = std::min(k, size());
  std::vector<std::size_t> indices(k);
  std::vector<double> dists(k);
  if (k == 0) return indices;
  nanoflann::KNNResultSet<double, std::size_t> result(k);
  result.init(indices.data(), dists.data());
  const Point q = embed(query, l_);
  index_->tree.findNeighbors(result, q.data(), nanoflann::SearchParams());
  // The dynamic index searches several sub-trees and returns their merged candidates; sort so the
  // result is nearest first with a fixed order among equal distances.
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < result.size(); ++i) order.emplace_back(dists[i], indices[i]);
  std::sort(order.begin(), order.end());
  indices.clear();
  for (const auto& [d, i] : order) indices.push_back(i);
  return indices;
}

// Called once per planner iteration: a one-slot result set on the stack, no allocation. Same
// answer as kNearest(query, 1)[0].
std::size_t NearestNeighbors::nearest(const Pose2& query) const {
  std::size_t index = 0;
  double dist = 0.0;
  nanoflann::KNNResultSet<double, std::size_t> result(1);
  result.init(&index, &dist);
  const Point q = embed(query, l_);
  index_->tree.findNeighbors(result, q.data(), nanoflann::SearchParams());
  return index;
}

std::vector<std::size_t> NearestNeighbors::withinRadius(const Pose2& query, double radius_m) const {
  std::vector<std::pair<std::size_t, double>> matches;
  // L2_Simple_Adaptor works in squared distances.
  nanoflann::RadiusResultSet<double, std::size_t> result(radius_m * radius_m, matches);
  const Point q = embed(query, l_);
  index_->tree.findNeighbors(result, q.data(), nanoflann::SearchParams());
  std::vector<std::pair<double, std::size_t>> order;
  for (const auto& [i, d] : matches) order.emplace_back(d, i);
  std::sort(order.begin(), order.end());
  std::vector<std::size_t> indices;
  for (const auto& [d, i] : order) indices.push_back(i);
  return indices;
}

double NearestNeighbors::distance(const Pose2& a, const Pose2& b) const {
  const Point pa = embed(a, l_), pb = embed(b, l_);
  double s = 0.0;
  for (int i = 0; i < 4; ++i) s += (pa[i] - pb[i]) * (pa[i] - pb[i]);
  return std::sqrt(s);
}

}  // namespace parksim
