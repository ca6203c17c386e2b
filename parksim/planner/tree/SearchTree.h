#pragma once
// Internal to TreePlanner: the nodes of one search tree, with their edges and costs, and a
// nearest-neighbour index over the nodes that may be extended.

#include <cstddef>
#include <utility>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/planner/motion/PathCost.h"
#include "parksim/planner/tree/NearestNeighbors.h"
#include "parksim/planner/tree/PathSegment.h"

namespace parksim::detail {

struct Node {
  Pose2 pose;
  WheelSpeeds arrival;  // start tree: wheel speeds on arrival, where the next edge starts from
  int parent = -1;
  PathSegment edge;        // start tree: parent -> node; goal tree: node -> parent
  MotionSummary motion;    // of the edge
  double cost = 0.0;       // start tree: cost of the path from the start
  int last_direction = 0;  // start tree: last driving direction on the path from the start
  bool goal_leaf = false;  // start tree: the edge ends in the goal region; never extended
  std::vector<int> children;
};

// The nodes of one tree, and a nearest-neighbour index over those that may be extended.
class Tree {
 public:
  explicit Tree(double heading_length_m) : nn_(heading_length_m) {}

  int add(Node node, bool indexed) {
    const int id = size();
    if (node.parent >= 0) nodes_[node.parent].children.push_back(id);
    nodes_.push_back(std::move(node));
    if (indexed) {
      nn_.add(nodes_.back().pose);
      indexed_.push_back(id);
    }
    return id;
  }
  Node& operator[](int id) { return nodes_[id]; }
  const Node& operator[](int id) const { return nodes_[id]; }
  int size() const { return static_cast<int>(nodes_.size()); }

  int nearest(const Pose2& q) const { return indexed_[nn_.nearest(q)]; }
  std::vector<int> kNearest(const Pose2& q, std::size_t k) const {
    return toIds(nn_.kNearest(q, k));
  }
  std::vector<int> withinRadius(const Pose2& q, double r) const {
    return toIds(nn_.withinRadius(q, r));
  }
  double distance(const Pose2& a, const Pose2& b) const { return nn_.distance(a, b); }
  std::size_t indexedCount() const { return indexed_.size(); }

 private:
  std::vector<int> toIds(const std::vector<std::size_t>& idx) const {
    std::vector<int> ids;
    ids.reserve(idx.size());
    for (std::size_t i : idx) ids.push_back(indexed_[i]);
    return ids;
  }

  std::vector<Node> nodes_;
  NearestNeighbors nn_;
  std::vector<int> indexed_;  // node id of each index entry
};

}  // namespace parksim::detail
