#pragma once
// What a process running user code (a plugin's or a Python object's planner or controller)
// publishes to the process that watches it (usercode/UserCodeIsolation.h), in memory they
// share: which component it is in, and that the component is making progress. Lock-free
// atomics, so the parent reads them while the child runs; plain data, so it lives in an
// anonymous shared mapping.

#include <atomic>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

/// Time limits on user code watched this way, s (> 0). docs/limits.md.
struct UserCodeLimits {
  /// Longest a user's planner may plan for one episode.
  double planner_s = 600.0;
  /// Longest a user's controller may take for one command (its reset included).
  double controller_tick_s = 10.0;

  /// Longest a plugin's loading may take in the child that probes it (usercode/PluginLoader.h):
  /// its static initializers, entry point and registration. Of the order of a controller
  /// command's start (CommandControllerDef::start_timeout_s): loading is a start, not work.
  static constexpr double kPluginLoadS = 30.0;

  /// The range of every limit, s.
  static constexpr double kMin = 0.001;
  static constexpr double kMax = 1e6;
};

/// Throws Error unless both limits are in [kMin, kMax].
inline void checkUserCodeLimits(const UserCodeLimits& limits) {
  for (const auto& [name, value] : {std::pair<const char*, double>{"planner", limits.planner_s},
                                    {"controller", limits.controller_tick_s}}) {
    if (!(value >= UserCodeLimits::kMin && value <= UserCodeLimits::kMax)) {
      throw Error(std::string(name) + " time limit: must be in [" +
                  formatGeneral(UserCodeLimits::kMin) + ", " + formatGeneral(UserCodeLimits::kMax) +
                  "] s, got " + formatGeneral(value));
    }
  }
}

class UserCodeWatch {
 public:
  enum class Phase : int { kParksim = 0, kPlanner = 1, kController = 2 };

  /// The process enters `phase`, running the component `name` (kept to 64 bytes). Every entry
  /// counts as progress: the watcher starts the phase's time limit again.
  void enter(Phase phase, const std::string& name) {
    const std::size_t n = std::min(name.size(), sizeof name_ - 1);
    std::memcpy(name_, name.data(), n);
    name_[n] = '\0';
    beats_.fetch_add(1, std::memory_order_relaxed);
    phase_.store(static_cast<int>(phase), std::memory_order_release);
  }

  Phase phase() const { return static_cast<Phase>(phase_.load(std::memory_order_acquire)); }
  std::uint64_t beats() const { return beats_.load(std::memory_order_relaxed); }
  std::string name() const { return std::string(name_, strnlen(name_, sizeof name_)); }

 private:
  std::atomic<int> phase_{0};
  std::atomic<std::uint64_t> beats_{0};
  char name_[65] = {};
};

static_assert(std::atomic<int>::is_always_lock_free &&
                  std::atomic<std::uint64_t>::is_always_lock_free,
              "the watch is shared between processes: its atomics must not need a lock");

}  // namespace parksim
