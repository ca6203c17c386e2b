#include "parksim/report/BoxPlot.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/stats/Quantile.h"
#include "parksim/renders/plots/TrackingPlot.h"
#include "parksim/report/PlotCanvas.h"

namespace parksim {

BoxStats boxStats(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  BoxStats s;
  s.q1 = quantileSorted7(values, 0.25);
  s.median = quantileSorted7(values, 0.5);
  s.q3 = quantileSorted7(values, 0.75);
  const double iqr = s.q3 - s.q1;
  const double lo_fence = s.q1 - 1.5 * iqr;
  const double hi_fence = s.q3 + 1.5 * iqr;
  s.whisker_lo = s.q1;
  s.whisker_hi = s.q3;
  for (const double v : values) {
    if (v < lo_fence || v > hi_fence) {
      s.outliers.push_back(v);
    } else {
      s.whisker_lo = std::min(s.whisker_lo, v);
      s.whisker_hi = std::max(s.whisker_hi, v);
    }
  }
  return s;
}

Scene buildBoxPlot(const std::vector<BoxSeries>& series, const std::string& title,
                   const std::string& y_label, int width_px, int height_px,
                   const SceneStyle& style) {
  Scene scene;
  PlotCanvas c(scene, width_px, height_px);
  const double size = style.text_px;
  const double left = 6.0 * size;
  const double right = width_px - 1.5 * size;
  const double top = 3.6 * size;
  const double bottom = height_px - 5.0 * size;

  double lo = 0.0;
  double hi = 0.0;
  bool any = false;
  for (const BoxSeries& s : series) {
    for (const double v : s.values) {
      lo = any ? std::min(lo, v) : v;
      hi = any ? std::max(hi, v) : v;
      any = true;
    }
  }
  lo = std::min(lo, 0.0);  // the quantities plotted are sizes: show them against zero
  if (!(hi > lo)) hi = lo + 1.0;
  hi += 0.06 * (hi - lo);
  auto py = [&](double v) { return bottom - (v - lo) / (hi - lo) * (bottom - top); };

  c.text(title, 0.5 * width_px, 0.6 * size, static_cast<float>(1.2 * size), style.text,
         HAlign::kCenter, VAlign::kTop);
  c.text(y_label, left, top - 0.5 * size, static_cast<float>(size), style.text, HAlign::kLeft,
         VAlign::kBottom);
  c.fillRect(left, top, right, bottom, rgb(255, 255, 255), 0.0);
  const std::vector<double> ticks = niceTicks(lo, hi, 6);
  for (const double t : ticks) {
    c.line(left, py(t), right, py(t), style.grid, style.grid_px, 0.001);
    c.line(left - 0.4 * size, py(t), left, py(t), style.axis, style.grid_px, 0.003);
    if (ticks.size() > 1) {
      c.text(formatTick(t, ticks[1] - ticks[0]), left - 0.7 * size, py(t), static_cast<float>(size),
             style.text, HAlign::kRight, VAlign::kMiddle);
    }
  }
  c.outlineRect(left, top, right, bottom, style.axis, style.border_px, 0.003);

  const double slot = (right - left) / std::max<std::size_t>(1, series.size());
  const double half = std::min(0.3 * slot, 4.0 * size);
  for (std::size_t i = 0; i < series.size(); ++i) {
    const double x = left + (static_cast<double>(i) + 0.5) * slot;
    const std::string& label = series[i].label;
    const std::size_t nl = label.find('\n');
    c.text(label.substr(0, nl), x, bottom + 0.6 * size, static_cast<float>(size), style.text,
           HAlign::kCenter, VAlign::kTop);
    if (nl != std::string::npos) {
      c.text(label.substr(nl + 1), x, bottom + 2.0 * size, static_cast<float>(size), style.text,
             HAlign::kCenter, VAlign::kTop);
    }
    if (series[i].values.empty()) {
      c.text("no data", x, 0.5 * (top + bottom), static_cast<float>(size), style.axis,
             HAlign::kCenter, VAlign::kMiddle);
      continue;
    }
    const BoxStats b = boxStats(series[i].values);
    const Rgba8 fill = rgb(190, 210, 240);
    c.fillRect(x - half, py(b.q3), x + half, py(b.q1), fill, 0.0005);
    c.outlineRect(x - half, py(b.q3), x + half, py(b.q1), style.planned, style.outline_px, 0.004);
    c.line(x - half, py(b.median), x + half, py(b.median), style.executed, style.path_px, 0.005);
    c.line(x, py(b.q3), x, py(b.whisker_hi), style.planned, style.outline_px, 0.004);
    c.line(x, py(b.q1), x, py(b.whisker_lo), style.planned, style.outline_px, 0.004);
    c.line(x - 0.5 * half, py(b.whisker_hi), x + 0.5 * half, py(b.whisker_hi), style.planned,
           style.outline_px, 0.004);
    c.line(x - 0.5 * half, py(b.whisker_lo), x + 0.5 * half, py(b.whisker_lo), style.planned,
           style.outline_px, 0.004);
    const double r = 0.25 * size;
    for (const double v : b.outliers) {
      c.line(x - r, py(v) - r, x + r, py(v) + r, style.axis, style.outline_px, 0.004);
      c.line(x - r, py(v) + r, x + r, py(v) - r, style.axis, style.outline_px, 0.004);
    }
  }
  return scene;
}

}  // namespace parksim
