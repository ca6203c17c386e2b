#include "parksim/planner/steering/ReedsSheppSteering.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/planner/steering/OmplPlugin.h"

namespace parksim {

struct ReedsSheppSteering::Curve {
  // Segment types of OmplApi.h's reeds_shepp_path.
  static constexpr int kNone = 0;
  static constexpr int kLeft = 1;
  static constexpr int kRight = 3;

  struct Path {
    int types[5];
    double lengths[5];  // signed, in radii
    double total;       // in radii
  };

  explicit Curve(double radius)
      : space(plugin.api().reeds_shepp_new(radius), plugin.api().reeds_shepp_delete) {}

  Path path(const Pose2& from, const Pose2& to) const {
    const double a[3] = {from.x, from.y, from.theta};
    const double b[3] = {to.x, to.y, to.theta};
    Path p;
    plugin.api().reeds_shepp_path(space.get(), a, b, p.types, p.lengths, &p.total);
    return p;
  }

  OmplPlugin plugin;
  std::unique_ptr<void, void (*)(void*)> space;  // OMPL's state space, freed by the plugin
};

ReedsSheppSteering::ReedsSheppSteering(const RobotDef& robot, const ReedsSheppDef& def)
    : robot_(robot), def_(def) {
  def_.horizon_s = steeringHorizon(def.horizon_s, robot);
  // A car's arcs are no tighter than it can steer.
  if (robot.isCar()) {
    def_.turning_radius_m = std::max(def.turning_radius_m, robot.minTurningRadius());
  }
  if (!(def.turning_radius_m > 0.0)) throw Error("reeds-shepp steering: radius must be positive");
  if (!(def.period_s > 0.0) || !(def_.horizon_s > 0.0)) {
    throw Error("reeds-shepp steering: period and horizon must be positive");
  }
  if (!(def.speed_fraction > 0.0 && def.speed_fraction <= 1.0)) {
    throw Error("reeds-shepp steering: speed fraction must be in (0, 1]");
  }
  if (!(robot.max_wheel_speed_radps > 0.0) || !(robot.max_wheel_accel_radps2 > 0.0)) {
    throw Error("reeds-shepp steering: wheel speed and accel limits must be positive");
  }
  curve_ = std::make_unique<Curve>(def_.turning_radius_m);
}

ReedsSheppSteering::~ReedsSheppSteering() = default;

std::vector<PathPiece> ReedsSheppSteering::pieces(const Pose2& from, const Pose2& to) const {
  const auto path = curve_->path(from, to);
  const double rho = def_.turning_radius_m;
  std::vector<PathPiece> out;
  for (int i = 0; i < 5; ++i) {
    const double d = path.lengths[i] * rho;  // signed: negative drives backwards, m
    if (path.types[i] == Curve::kNone || !(std::abs(d) > 1e-12)) continue;
    double kappa = 0.0;
    if (path.types[i] == Curve::kLeft) kappa = 1.0 / rho;
    if (path.types[i] == Curve::kRight) kappa = -1.0 / rho;
    // Moving d metres at curvature kappa turns the heading by d * kappa, in 1 s here.
    out.push_back(pieceOf(toWheelSpeeds({d, d * kappa}, robot_), 1.0));
  }
  return out;
}

double ReedsSheppSteering::distance(const Pose2& from, const Pose2& to) const {
  return curve_->path(from, to).total * def_.turning_radius_m;
}

SteerResult ReedsSheppSteering::steer(const Pose2& from, const WheelSpeeds& from_wheels,
                                      const Pose2& to, SteerMode mode) const {
  const TimingLimits limits{def_.speed_fraction * robot_.max_wheel_speed_radps,
                            robot_.max_wheel_accel_radps2, def_.period_s};
  return steerThroughPieces(from, from_wheels, to, mode, robot_, limits, def_.horizon_s,
                            [&](const Pose2& at_rest) { return pieces(at_rest, to); });
}

}  // namespace parksim
