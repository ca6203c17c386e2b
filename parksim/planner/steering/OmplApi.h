#pragma once
// What parksim takes from OMPL, as a table of C functions. OMPL (with Boost and ODE behind it)
// costs a process about 17,000 symbol bindings at start-up, half of `parksim --version`, yet
// only Reeds-Shepp curves and the names of planner statuses need it. So libompl is linked into
// a plugin of its own, libparksim_ompl_plugin.so (OmplApi.cpp, the one file that includes
// OMPL's library headers), which OmplPlugin.h loads when first needed. The symbol's version
// suffix changes whenever this table does, so a stale plugin is refused, not misread.

extern "C" {

struct ParksimOmplApi {
  /// A Reeds-Shepp state space (OMPL's ReedsSheppStateSpace) for arcs of `radius` m.
  void* (*reeds_shepp_new)(double radius);
  void (*reeds_shepp_delete)(void* space);
  /// The shortest Reeds-Shepp path between poses {x m, y m, yaw rad}: up to five segments, each
  /// a type (0 none, 1 left arc, 2 straight, 3 right arc) and a signed length in radii
  /// (negative: backwards), and their total absolute length in radii. Thread-safe.
  void (*reeds_shepp_path)(const void* space, const double from[3], const double to[3],
                           int types[5], double lengths[5], double* total);
  /// OMPL's name of planner status `code` (ompl::base::PlannerStatus::StatusType), or null for
  /// a code outside [0, TYPE_COUNT).
  const char* (*status_name)(int code);
};

/// The plugin's one exported symbol.
const ParksimOmplApi* parksim_ompl_api_v1();
}

#define PARKSIM_OMPL_API_SYMBOL "parksim_ompl_api_v1"
