#pragma once
// Exact nearest neighbours of planar poses under an SE(2) metric. Poses are embedded as
// (x, y, l cos theta, l sin theta): position in metres plus the chord a point at distance l from
// the reference point travels when the heading changes, so metres are never added to radians.
// Backed by nanoflann's dynamic k-d tree, which keeps exact answers while nodes are added.

#include <cstddef>
#include <memory>
#include <vector>

#include "parksim/core/geometry/Pose2.h"

namespace parksim {

class NearestNeighbors {
 public:
  /// `heading_length_m` is l in the embedding; > 0.
  explicit NearestNeighbors(double heading_length_m);
  ~NearestNeighbors();
  NearestNeighbors(const NearestNeighbors&) = delete;
  NearestNeighbors& operator=(const NearestNeighbors&) = delete;

  /// Adds a pose; its index is the number of poses added before it.
  std::size_t add(const Pose2& pose);
  std::size_t size() const;

  /// Index of the nearest pose. Requires size() > 0.
  std::size_t nearest(const Pose2& query) const;
  /// Indices of the k nearest poses, nearest first.
  std::vector<std::size_t> kNearest(const Pose2& query, std::size_t k) const;
  /// Indices of all poses within `radius_m`, nearest first.
  std::vector<std::size_t> withinRadius(const Pose2& query, double radius_m) const;

  /// The metric itself, m.
  double distance(const Pose2& a, const Pose2& b) const;

 private:
  struct Index;
  double l_;
  std::unique_ptr<Index> index_;
};

}  // namespace parksim
