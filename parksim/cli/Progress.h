#pragma once
// A one-line progress display on stderr for commands that run longer than a second:
// "frames: 120/996 (12%), 54.3/s, ETA 16 s". Drawn only when enabled (stderr is a terminal, or
// --progress) and no more than five times a second; the wall clock only paces the display.

#include <chrono>
#include <string>

#include "parksim/planner/base/PlanResult.h"

namespace parksim::cli {

/// Whether commands draw progress: on a terminal unless -q, always with --progress.
bool progressWanted(bool forced, bool quiet);

class Progress {
 public:
  /// `what` labels the line, `total` > 0 is the count at completion.
  Progress(std::string what, long total, bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Reports `done` of the total items finished.
  void update(long done);
  /// Draws the final count and ends the line (also done by the destructor).
  void finish();

 private:
  void draw(long done);

  using Clock = std::chrono::steady_clock;
  std::string what_;
  long total_;
  bool enabled_;
  bool drawn_ = false;
  bool finished_ = false;
  long done_ = 0;
  Clock::time_point start_;
  Clock::time_point last_draw_;
};

/// Marks a progress line as drawn on stderr without its newline (true) or ended (false); Progress
/// does this itself, other progress lines (the sweep's) call it.
void markProgressLineOpen(bool open);

/// Ends an open progress line with a newline (and forgets it). For the thread that handles
/// SIGINT, SIGTERM or SIGHUP before the process dies of it: the shell's prompt then starts on
/// a line of its own, and a log does not end in a cut-off line.
void endOpenProgressLine();

/// A progress line for a planner's search ("planning (hybrid-a-star expansions): 1200/20000
/// ..."): `budget` is the planner's iteration budget; a search that succeeds ends early.
/// The returned callback feeds `progress`, which must outlive it.
PlanProgress planProgress(Progress& progress);

}  // namespace parksim::cli
