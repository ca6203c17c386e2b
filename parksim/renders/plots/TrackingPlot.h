#pragma once
// The tracking-error-versus-time plot: position error (mm) and heading error (degrees) of the
// executed pose against the planned pose at the same time, in two panels with axes, ticks and
// labels. Built as a Scene in pixel units, so the same renderer draws it.

#include <string>
#include <string_view>
#include <vector>

#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

/// One row per sample; the three vectors have the same length.
struct TrackingSeries {
  std::vector<double> t_s;                ///< s
  std::vector<double> position_error_m;   ///< m, >= 0
  std::vector<double> heading_error_rad;  ///< rad, signed
};

/// The plot as a Scene whose world units are pixels (extent 0..width x 0..height, y up); draw it
/// with the top-down camera at width_px x height_px. Throws Error when the vectors differ in
/// length.
Scene buildTrackingPlot(const TrackingSeries& series, const std::string& title, int width_px,
                        int height_px, const SceneStyle& style);

/// Reads a CSV file with a header row. Columns are found by name: time `t` (or `t_s`, `time`),
/// position error `pos_err` (or `pos_err_m`, `position_error`, `position_error_m`), heading
/// error `heading_err` (or `heading_err_rad`, `heading_error`, `heading_error_rad`; names ending
/// in `_deg` are read as degrees). Other columns are ignored. Throws Error naming the file and
/// line on bad input.
TrackingSeries readTrackingCsv(const std::string& path);

/// The names readTrackingCsv accepts for each column it reads, for checks of the same file.
inline constexpr std::string_view kTrackingTimeNames[] = {"t", "t_s", "time"};
inline constexpr std::string_view kTrackingPositionNames[] = {"pos_err", "pos_err_m",
                                                              "position_error", "position_error_m"};
inline constexpr std::string_view kTrackingHeadingRadNames[] = {
    "heading_err", "heading_err_rad", "heading_error", "heading_error_rad"};
inline constexpr std::string_view kTrackingHeadingDegNames[] = {"heading_err_deg",
                                                                "heading_error_deg"};

/// A tick label with as many decimals as the step between ticks needs.
std::string formatTick(double value, double step);

/// About `target` round tick values (steps of 1, 2 or 5 times a power of ten) covering [lo, hi].
std::vector<double> niceTicks(double lo, double hi, int target);

}  // namespace parksim
