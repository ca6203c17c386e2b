#pragma once
// Whether the robot fits at a position in some heading, from the obstacles' shapes: the free
// test of the search heuristic's grid (ObstacleHeuristic.h), which asks it for every cell of a
// window. The footprint, grown by a margin, is tested at evenly spread headings against the
// obstacles near the position (found in buckets of about the footprint's size; a compound
// obstacle's parts each on their own) with core's exact separating-axis separation. A heuristic's
// answer: the searches check every move with the MotionValidator; this only has to be fast, ~10x
// the Bullet query per cell.

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"

namespace parksim {

class FootprintFit {
 public:
  /// `obstacles` that block the robot (blocksRobot) count; `headings` >= 1 evenly spread.
  FootprintFit(const std::vector<Obstacle>& obstacles, const RobotDef& robot, double margin_m,
               int headings = 8);

  /// True when the footprint grown by the margin overlaps no obstacle at (x, y) in at least one
  /// of the headings.
  bool fitsSomeHeading(double x, double y) const;

 private:
  // A box, circle or convex polygon, or one part of a compound obstacle.
  struct Shape {
    Obstacle obstacle;                              // unless a part
    std::shared_ptr<const CompoundShape> compound;  // a part's obstacle
    std::size_t part = 0;                           // its index there
    double x_min, y_min, x_max, y_max;              // bounding box
    BoxAxes axes{};                                 // a box's own axes
  };
  void add(Shape shape);
  double separationOf(const OrientedBox& footprint, const BoxAxes& axes, const Shape& shape) const;
  std::int64_t bucketKey(std::int64_t i, std::int64_t j) const { return i * 4194304 + j; }

  RobotDef robot_;
  double margin_m_;
  int headings_;
  double reach_m_;   // farthest grown-footprint point from the reference point
  double bucket_m_;  // bucket side
  // The grown footprint at each heading with its reference point at the origin, and its axes:
  // the grid asks every cell in every heading, and their sines and cosines were most of its
  // time.
  std::vector<OrientedBox> footprints_;
  std::vector<BoxAxes> footprint_axes_;
  std::vector<Shape> shapes_;
  std::unordered_map<std::int64_t, std::vector<int>> buckets_;
};

}  // namespace parksim
