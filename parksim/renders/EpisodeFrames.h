#pragma once
// The bridge from a simulated episode to a film: turns the simulation's observer sample into
// the recorder's plain input. Header-only so that parksim_render itself does not depend on
// parksim_sim; include it where both are linked (the CLI, the Python module, your program).

#include "parksim/renders/FrameRecorder.h"
#include "parksim/sim/Episode.h"

namespace parksim {

/// What FrameRecorder::addFrame needs from one observer call of runEpisode.
inline FrameInput frameInput(const EpisodeSample& sample) {
  FrameInput in;
  in.t_s = sample.tracking.t_s;
  in.pose = sample.tracking.pose;
  in.reference = sample.tracking.reference;
  in.position_error_m = sample.tracking.pos_err_m;
  in.heading_error_rad = sample.tracking.heading_err_rad;
  in.obstacle_poses = sample.obstacles;
  in.contacts = sample.contacts;
  return in;
}

}  // namespace parksim
