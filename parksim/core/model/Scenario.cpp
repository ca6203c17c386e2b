#include "parksim/core/model/Scenario.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace parksim {

namespace {

OrientedBox boundingRectangle(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d lo = points.front();
  Eigen::Vector2d hi = points.front();
  for (const Eigen::Vector2d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  OrientedBox box;
  box.center = 0.5 * (lo + hi);
  box.half_extents = 0.5 * (hi - lo);
  return box;
}

// Shortest text that reads back as the same double, for messages.
std::string shortest(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

// Up to 4 significant digits, for distances in messages.
std::string brief(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 4);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

}  // namespace

const char* toString(ObstacleKind kind) {
  switch (kind) {
    case ObstacleKind::kWall: return "wall";
    case ObstacleKind::kCurb: return "curb";
    case ObstacleKind::kIsland: return "island";
    case ObstacleKind::kBox: return "box";
    case ObstacleKind::kBollard: return "bollard";
    case ObstacleKind::kPillar: return "pillar";
    case ObstacleKind::kParkedRobot: return "parked_robot";
  }
  return "box";
}

Obstacle Obstacle::makeBox(std::string name, ObstacleKind kind, const OrientedBox& box,
                           double height_m) {
  Obstacle o;
  o.name = std::move(name);
  o.kind = kind;
  o.box = box;
  o.height_m = height_m;
  return o;
}

Obstacle Obstacle::makeCircle(std::string name, ObstacleKind kind, const Circle& circle,
                              double height_m) {
  Obstacle o;
  o.name = std::move(name);
  o.kind = kind;
  o.shape = ObstacleShape::kCircle;
  o.box.center = circle.center;
  o.box.half_extents = {circle.radius, circle.radius};
  o.radius_m = circle.radius;
  o.height_m = height_m;
  return o;
}

Obstacle Obstacle::makePolygon(std::string name, ObstacleKind kind,
                               std::vector<Eigen::Vector2d> vertices, double height_m) {
  Obstacle o;
  o.name = std::move(name);
  o.kind = kind;
  o.shape = ObstacleShape::kPolygon;
  if (!vertices.empty()) o.box = boundingRectangle(vertices);
  o.vertices = std::move(vertices);
  o.height_m = height_m;
  return o;
}

Obstacle Obstacle::makeCompound(std::string name, ObstacleKind kind,
                                std::shared_ptr<const CompoundShape> compound, double height_m) {
  Obstacle o;
  o.name = std::move(name);
  o.kind = kind;
  o.shape = ObstacleShape::kCompound;
  o.box.center = compound->extent.center();
  o.box.half_extents = 0.5 * compound->extent.sizes();
  o.compound = std::move(compound);
  o.height_m = height_m;
  return o;
}

namespace {

Eigen::AlignedBox2d boundsOf(const OrientedBox& box) {
  Eigen::AlignedBox2d b;
  b.setEmpty();
  for (const Eigen::Vector2d& c : box.corners()) b.extend(c);
  return b;
}

// Gap between two axis-aligned boxes, m: positive when apart (a lower bound of the gap between
// anything inside them), otherwise <= 0.
double boundsGap(const Eigen::AlignedBox2d& a, const Eigen::AlignedBox2d& b) {
  const Eigen::Vector2d gap = (a.min() - b.max()).cwiseMax(b.min() - a.max());
  return gap.maxCoeff();
}

// A compound obstacle overlaps the footprint exactly when one of its parts does (their union is
// the obstacle); apart, the smallest part's gap (parts whose bounds are apart count with the
// bounds' gap, also a lower bound).
double compoundSeparation(const OrientedBox& footprint, const CompoundShape& shape) {
  const Eigen::AlignedBox2d fb = boundsOf(footprint);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < shape.parts.size(); ++i) {
    const double gap = boundsGap(fb, shape.bounds[i]);
    best = std::min(best, gap > 0.0 ? gap : separationAlongAxes(footprint, shape.parts[i]));
  }
  return best;
}

double compoundDistance(const OrientedBox& footprint, const CompoundShape& shape) {
  const Eigen::AlignedBox2d fb = boundsOf(footprint);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < shape.parts.size() && best > 0.0; ++i) {
    if (boundsGap(fb, shape.bounds[i]) >= best) continue;
    best = std::min(best, distance(footprint, shape.parts[i]));
  }
  return best;
}

}  // namespace

double separation(const OrientedBox& footprint, const Obstacle& obstacle) {
  switch (obstacle.shape) {
    case ObstacleShape::kBox: return separationAlongAxes(footprint, obstacle.box);
    case ObstacleShape::kCircle: return separation(footprint, obstacle.circle());
    case ObstacleShape::kPolygon: return separationAlongAxes(footprint, obstacle.vertices);
    case ObstacleShape::kCompound: return compoundSeparation(footprint, *obstacle.compound);
  }
  return separationAlongAxes(footprint, obstacle.box);
}

double distance(const OrientedBox& footprint, const Obstacle& obstacle) {
  switch (obstacle.shape) {
    case ObstacleShape::kBox: return distance(footprint, obstacle.box);
    case ObstacleShape::kCircle: return std::max(0.0, separation(footprint, obstacle.circle()));
    case ObstacleShape::kPolygon: return distance(footprint, obstacle.vertices);
    case ObstacleShape::kCompound: return compoundDistance(footprint, *obstacle.compound);
  }
  return distance(footprint, obstacle.box);
}

std::vector<Eigen::Vector2d> outline(const Obstacle& obstacle, int circle_segments) {
  switch (obstacle.shape) {
    case ObstacleShape::kBox: {
      const auto c = obstacle.box.corners();
      return {c.begin(), c.end()};
    }
    case ObstacleShape::kCircle: {
      const int n = std::max(3, circle_segments);
      std::vector<Eigen::Vector2d> out;
      out.reserve(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        const double a = 2.0 * kPi * i / n;
        out.push_back(obstacle.box.center +
                      obstacle.radius_m * Eigen::Vector2d(std::cos(a), std::sin(a)));
      }
      return out;
    }
    case ObstacleShape::kPolygon: return obstacle.vertices;
    case ObstacleShape::kCompound: {
      const auto c = obstacle.box.corners();
      return {c.begin(), c.end()};
    }
  }
  return {};
}

std::vector<std::vector<Eigen::Vector2d>> convexPieces(const Obstacle& obstacle,
                                                       int circle_segments) {
  if (obstacle.shape == ObstacleShape::kCompound) return obstacle.compound->parts;
  return {outline(obstacle, circle_segments)};
}

bool blocksRobot(const Obstacle& obstacle, const RobotDef& robot) {
  return obstacle.height_m > robot.ground_clearance_m;
}

double motionCheckResolution(const RobotDef& robot) {
  return kStudyMotionCheckResolution_m * robot.sizeScale();
}

double placementMargin(const RobotDef& robot) { return 0.5 * motionCheckResolution(robot); }

std::optional<std::string> placementProblem(const Scenario& s, const Pose2& pose,
                                            std::optional<double> margin) {
  const double margin_m = margin ? *margin : placementMargin(s.robot);
  const std::string margin_text = brief(margin_m * 1000.0) + " mm";
  const double inset = margin_m - kPlacementTolerance_m;
  const LotBounds& lot = s.lot;
  if (!(pose.x >= lot.x_min_m + inset && pose.x <= lot.x_max_m - inset &&
        pose.y >= lot.y_min_m + inset && pose.y <= lot.y_max_m - inset)) {
    const bool outside = !lot.contains(pose.x, pose.y);
    return "reference point (" + shortest(pose.x) + ", " + shortest(pose.y) + ") is " +
           (outside ? "outside the lot"
                    : "closer than the " + margin_text + " margin to the lot edge") +
           " [" + shortest(lot.x_min_m) + ", " + shortest(lot.x_max_m) + "] x [" +
           shortest(lot.y_min_m) + ", " + shortest(lot.y_max_m) + "]";
  }
  const OrientedBox grown = footprintAt(s.robot, pose, margin_m);
  const OrientedBox footprint = footprintAt(s.robot, pose);
  for (const Obstacle& obstacle : s.obstacles) {
    if (!blocksRobot(obstacle, s.robot)) continue;
    if (separation(grown, obstacle) >= -kPlacementTolerance_m) continue;
    const std::string name = "obstacle \"" + obstacle.name + "\"";
    if (separation(footprint, obstacle) < -kPlacementTolerance_m) {
      return "robot footprint overlaps " + name;
    }
    return "robot footprint is " + brief(distance(footprint, obstacle) * 1000.0) + " mm from " +
           name + "; start and goal keep at least the " + margin_text +
           " margin of the planner's motion checks";
  }
  return std::nullopt;
}

std::optional<std::string> goalPlacementProblem(const Scenario& s, std::optional<double> margin_m) {
  std::optional<std::string> problem = placementProblem(s, s.goal.pose, margin_m);
  if (problem && s.goal.either_heading) {
    const Pose2 turned{s.goal.pose.x, s.goal.pose.y, wrapAngle(s.goal.pose.theta + kPi)};
    if (!placementProblem(s, turned, margin_m)) return std::nullopt;
    *problem += " (in both accepted headings)";
  }
  return problem;
}

double goalHeadingError(const GoalRegion& goal, double theta) {
  double err = std::abs(angleDiff(theta, goal.pose.theta));
  if (goal.either_heading) err = std::min(err, std::abs(angleDiff(theta, goal.pose.theta + kPi)));
  return err;
}

}  // namespace parksim
