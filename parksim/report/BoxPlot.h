#pragma once
// Box plots of several samples side by side (Tukey's: box from the first to the third
// quartile, median line, whiskers to the furthest values within 1.5 IQR of the box, values
// beyond them as points), built as a Scene in pixel units like the tracking plot.

#include <string>
#include <vector>

#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

struct BoxSeries {
  std::string label;           ///< under its box; '\n' starts a second line
  std::vector<double> values;  ///< may be empty (drawn as "no data")
};

/// The five numbers a box shows, from sorted values (linear interpolation between ranks).
struct BoxStats {
  double q1 = 0.0, median = 0.0, q3 = 0.0;
  double whisker_lo = 0.0, whisker_hi = 0.0;
  std::vector<double> outliers;
};

/// BoxStats of `values` (non-empty; any order).
BoxStats boxStats(std::vector<double> values);

Scene buildBoxPlot(const std::vector<BoxSeries>& series, const std::string& title,
                   const std::string& y_label, int width_px, int height_px,
                   const SceneStyle& style);

}  // namespace parksim
