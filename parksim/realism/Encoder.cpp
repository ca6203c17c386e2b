#include "parksim/realism/Encoder.h"

#include <cmath>

#include "parksim/core/geometry/Angle.h"

namespace parksim {

Encoder::Encoder(const EncoderDef& def) : def_(def) {}

double Encoder::resolution() const {
  return def_.counts_per_turn > 0.0 ? 2.0 * kPi / def_.counts_per_turn : 0.0;
}

double Encoder::read(double angle_rad, std::mt19937_64& rng) {
  if (!(def_.counts_per_turn > 0.0)) {
    if (def_.noise_counts > 0.0) {
      std::normal_distribution<double> n(0.0, def_.noise_counts);
      return angle_rad + n(rng);
    }
    return angle_rad;
  }
  double counts = angle_rad / resolution();
  if (def_.noise_counts > 0.0) {
    std::normal_distribution<double> n(0.0, def_.noise_counts);
    counts += n(rng);
  }
  count_ = static_cast<std::int64_t>(std::floor(counts));
  return static_cast<double>(count_) * resolution();
}

}  // namespace parksim
