#pragma once
// A wheel encoder: counts of the wheel's true angle, quantised to counts_per_turn, optionally
// with Gaussian jitter (edges seen early or late). Odometry and the wheel-speed loop read it.

#include <cstdint>
#include <random>

namespace parksim {

struct EncoderDef {
  /// Counts per wheel turn after the gearbox (all four edges counted); 0: the exact angle
  /// (no quantisation).
  double counts_per_turn = 0.0;
  /// Standard deviation of each reading's error, counts (0: none).
  double noise_counts = 0.0;
};

class Encoder {
 public:
  explicit Encoder(const EncoderDef& def);

  /// Reads the wheel at true angle `angle_rad`; returns the wheel angle it reports, rad.
  double read(double angle_rad, std::mt19937_64& rng);
  /// The last reading in counts (0 with counts_per_turn 0).
  std::int64_t count() const { return count_; }
  /// Angle of one count, rad (0 when unquantised).
  double resolution() const;

 private:
  EncoderDef def_;
  std::int64_t count_ = 0;
};

}  // namespace parksim
