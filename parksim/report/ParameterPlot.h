#pragma once
// A parameter study's plot: for each value (or bin of values) of one parameter, the share of
// episodes that met their tolerance with its interval (top panel), and the tracking error's
// median and 95th percentile (bottom panel), against the parameter. Built as a Scene in pixel
// units like the other statistical plots (PlotCanvas.h).

#include <optional>
#include <string>
#include <vector>

#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

struct ParameterPlotLevel {
  double x = 0.0;     ///< where on the axis: the value (its bin's centre), or its index
  std::string label;  ///< the value as text, for categorical axes
  double met_share = 0.0;
  double met_low = 0.0;  ///< the share's interval, 0..1
  double met_high = 0.0;
  std::optional<double> error_median;  ///< of the level's episodes that were driven
  std::optional<double> error_p95;
};

struct ParameterPlotInput {
  std::string parameter;  ///< the axis's name (its column)
  bool numeric = true;    ///< false: levels are categories at x = 0, 1, ... with labels
  std::vector<ParameterPlotLevel> levels;
  std::string error_label = "max tracking error (mm)";
  /// Where success turns to failure (between two values), drawn as a vertical line.
  std::optional<double> boundary_x;
};

Scene buildParameterPlot(const ParameterPlotInput& input, const std::string& title, int width_px,
                         int height_px, const SceneStyle& style);

}  // namespace parksim
