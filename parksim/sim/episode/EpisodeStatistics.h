#pragma once
// Running maxima and sums of squares over an episode's measured instants: the max and RMS
// fields of EpisodeMetrics. Internal to sim/ (Episode.cpp feeds it every step).

#include "parksim/sim/episode/EpisodeMetrics.h"
#include "parksim/sim/episode/ExecutedRow.h"

namespace parksim {

class EpisodeStatistics {
 public:
  /// One measured instant: its tracking errors and both wheels' slip; with `realism`, also the
  /// estimate's error, the motors' torque and effort (an ideal robot has none).
  void add(const ExecutedRow& row, bool realism);

  /// Instants added so far.
  long count() const { return count_; }

  /// Writes the max and RMS fields of `m` over the instants added (tracking, estimate, slip,
  /// motors); at least one instant must have been added.
  void report(EpisodeMetrics& m) const;

 private:
  long count_ = 0;
  double max_pos_ = 0.0;
  double sum_sq_pos_ = 0.0;
  double max_heading_ = 0.0;
  double sum_sq_heading_ = 0.0;
  double max_est_pos_ = 0.0;
  double sum_sq_est_pos_ = 0.0;
  double max_est_heading_ = 0.0;
  double max_slip_ = 0.0;
  double sum_sq_slip_ = 0.0;
  long slipping_ = 0;
  double max_torque_ = 0.0;
  double max_effort_ = 0.0;
};

}  // namespace parksim
