#include "parksim/realism/PoseSensor.h"

#include <cmath>

#include "parksim/core/geometry/Angle.h"

namespace parksim {

PoseSensor::PoseSensor(const PoseSensorDef& def, double dt_s)
    : def_(def), dt_(dt_s), latency_steps_(std::lround(def.latency_s / dt_s)) {}

void PoseSensor::observe(long step, const Pose2& truth, std::mt19937_64& rng) {
  if (!def_.enabled) return;
  const double t = static_cast<double>(step) * dt_;
  const double period = 1.0 / def_.rate_hz;
  if (t < static_cast<double>(next_sample_) * period - 1e-9 * dt_) return;
  while (static_cast<double>(next_sample_) * period - 1e-9 * dt_ <= t) ++next_sample_;
  ++taken_;
  // Every sample draws its noise and its dropout, kept or not, so a change of the dropout
  // probability does not shift the noise of the samples that are kept.
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double nx = n(rng);
  const double ny = n(rng);
  const double nt = n(rng);
  const bool lost = u(rng) < def_.dropout_probability;
  if (lost) {
    ++dropped_;
    return;
  }
  PoseMeasurement m;
  m.taken_step = step;
  m.arrival_step = step + latency_steps_;
  m.pose = {truth.x + def_.position_noise_m * nx, truth.y + def_.position_noise_m * ny,
            wrapAngle(truth.theta + def_.heading_noise_rad * nt)};
  in_flight_.push_back(m);
}

std::vector<PoseMeasurement> PoseSensor::deliver(long step) {
  std::vector<PoseMeasurement> out;
  while (!in_flight_.empty() && in_flight_.front().arrival_step <= step) {
    out.push_back(in_flight_.front());
    in_flight_.pop_front();
  }
  return out;
}

}  // namespace parksim
