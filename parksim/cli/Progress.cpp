#include "parksim/cli/Progress.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>

#include "parksim/core/io/NumberFormat.h"

namespace parksim::cli {

namespace {

// Whether a progress line is open on stderr: one stderr per process, so one flag per process,
// read by the signal-handling thread (OutputDir.cpp, the sweep command).
std::atomic<bool>& openLine() {
  static std::atomic<bool> open{false};
  return open;
}

}  // namespace

void markProgressLineOpen(bool open) { openLine().store(open); }

void endOpenProgressLine() {
  if (openLine().exchange(false)) {
    std::fputc('\n', stderr);
    std::fflush(stderr);
  }
}

bool progressWanted(bool forced, bool quiet) {
  if (forced) return true;
  return !quiet && isatty(STDERR_FILENO) == 1;
}

Progress::Progress(std::string what, long total, bool enabled)
    : what_(std::move(what)),
      total_(std::max(total, 1L)),
      enabled_(enabled),
      start_(Clock::now()),
      last_draw_(start_) {}

Progress::~Progress() { finish(); }

void Progress::update(long done) {
  done_ = done;
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  // Nothing for the first second (short commands stay quiet), then at most 5 lines a second.
  if (now - start_ < std::chrono::seconds(1) || now - last_draw_ < std::chrono::milliseconds(200)) {
    return;
  }
  last_draw_ = now;
  draw(done);
}

void Progress::draw(long done) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double rate = elapsed > 0.0 ? done / elapsed : 0.0;
  const long total = std::max(total_, done);  // an estimated total may be passed
  std::string line = what_ + ": " + std::to_string(done) + "/" + std::to_string(total) + " (" +
                     formatFixed(100.0 * done / total, 0) + "%), " +
                     // 3 significant digits, but never an exponent: "3860/s", "54.3/s".
                     (rate >= 1000.0 ? formatFixed(rate, 0) : formatGeneral(rate, 3)) + "/s";
  if (rate > 0.0 && done < total) {
    line += ", ETA " + formatFixed((total - done) / rate, 0) + " s";
  }
  std::fprintf(stderr, "\r%s\033[K", line.c_str());
  std::fflush(stderr);
  markProgressLineOpen(true);
  drawn_ = true;
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (!drawn_) return;  // never drawn: the command was short, leave no trace
  draw(done_);
  std::fputc('\n', stderr);
  markProgressLineOpen(false);
}

PlanProgress planProgress(Progress& progress) {
  return [&progress](long done, long) { progress.update(done); };
}

}  // namespace parksim::cli
