#include "parksim/report/ParameterPlot.h"

#include <algorithm>
#include <cmath>

#include "parksim/renders/plots/TrackingPlot.h"
#include "parksim/report/PlotCanvas.h"

namespace parksim {
namespace {

struct Box {
  double left, right, top, bottom;  // pixels
  double x_lo, x_hi, y_lo, y_hi;    // data
  double px(double x) const { return left + (x - x_lo) / (x_hi - x_lo) * (right - left); }
  double py(double y) const { return bottom - (y - y_lo) / (y_hi - y_lo) * (bottom - top); }
};

// Frame, grid, y ticks and the panel's label; x ticks (or category labels) when `x_labels`.
void drawAxes(PlotCanvas& c, const Box& b, const ParameterPlotInput& in, const std::string& label,
              bool x_labels, const SceneStyle& s) {
  const float size = s.text_px;
  const double tick = 0.4 * size;
  c.fillRect(b.left, b.top, b.right, b.bottom, rgb(255, 255, 255), 0.0);
  const std::vector<double> yt = niceTicks(b.y_lo, b.y_hi, 5);
  for (double y : yt) {
    c.line(b.left, b.py(y), b.right, b.py(y), s.grid, s.grid_px, 0.001);
    c.line(b.left - tick, b.py(y), b.left, b.py(y), s.axis, s.grid_px, 0.003);
    if (yt.size() > 1) {
      c.text(formatTick(y, yt[1] - yt[0]), b.left - 1.6 * tick, b.py(y), size, s.text,
             HAlign::kRight, VAlign::kMiddle);
    }
  }
  if (in.numeric) {
    const std::vector<double> xt = niceTicks(b.x_lo, b.x_hi, 8);
    for (double x : xt) {
      c.line(b.px(x), b.top, b.px(x), b.bottom, s.grid, s.grid_px, 0.001);
      c.line(b.px(x), b.bottom, b.px(x), b.bottom + tick, s.axis, s.grid_px, 0.003);
      if (x_labels && xt.size() > 1) {
        c.text(formatTick(x, xt[1] - xt[0]), b.px(x), b.bottom + 1.6 * tick, size, s.text,
               HAlign::kCenter, VAlign::kTop);
      }
    }
  } else {
    for (const ParameterPlotLevel& l : in.levels) {
      c.line(b.px(l.x), b.bottom, b.px(l.x), b.bottom + tick, s.axis, s.grid_px, 0.003);
      if (x_labels) {
        const std::string text = l.label.size() > 14 ? l.label.substr(0, 13) + "~" : l.label;
        c.text(text, b.px(l.x), b.bottom + 1.6 * tick, size, s.text, HAlign::kCenter, VAlign::kTop);
      }
    }
  }
  c.outlineRect(b.left, b.top, b.right, b.bottom, s.axis, s.border_px, 0.003);
  c.text(label, b.left, b.top - 0.5 * size, size, s.text, HAlign::kLeft, VAlign::kBottom);
}

void marker(PlotCanvas& c, double x, double y, double r, Rgba8 color) {
  c.fillRect(x - r, y - r, x + r, y + r, color, 0.004);
}

// A series through the levels that have a value: points, joined on a numeric axis.
template <class Get>
void series(PlotCanvas& c, const Box& b, const ParameterPlotInput& in, Get get, Rgba8 color,
            const SceneStyle& s) {
  const double r = 0.28 * s.text_px;
  std::optional<std::pair<double, double>> last;
  for (const ParameterPlotLevel& l : in.levels) {
    const std::optional<double> v = get(l);
    if (!v) continue;
    const double x = b.px(l.x);
    const double y = b.py(*v);
    marker(c, x, y, r, color);
    if (last && in.numeric) c.line(last->first, last->second, x, y, color, s.path_px, 0.002);
    last = {x, y};
  }
}

}  // namespace

Scene buildParameterPlot(const ParameterPlotInput& in, const std::string& title, int width_px,
                         int height_px, const SceneStyle& s) {
  Scene scene;
  PlotCanvas c(scene, width_px, height_px);
  const double w = width_px;
  const double h = height_px;
  const double size = s.text_px;
  const double left = 6.0 * size;
  const double right = w - 1.5 * size;
  const double top = 3.6 * size;
  const double bottom = h - 3.6 * size;
  const double gap = 3.6 * size;
  const double panel_h = std::max(10.0, 0.5 * (bottom - top - gap));

  double x_lo = 0.0;
  double x_hi = 1.0;
  if (!in.levels.empty()) {
    x_lo = in.levels.front().x;
    x_hi = in.levels.back().x;
    for (const ParameterPlotLevel& l : in.levels) {
      x_lo = std::min(x_lo, l.x);
      x_hi = std::max(x_hi, l.x);
    }
  }
  const double span = x_hi > x_lo ? x_hi - x_lo : std::max(1.0, std::abs(x_lo));
  const double pad = in.numeric ? 0.06 * span : 0.5;
  x_lo -= pad;
  x_hi += x_hi > x_lo + pad ? pad : pad + span;

  double e_hi = 0.0;
  for (const ParameterPlotLevel& l : in.levels) {
    e_hi = std::max({e_hi, l.error_median.value_or(0.0), l.error_p95.value_or(0.0)});
  }
  if (!(e_hi > 0.0)) e_hi = 1.0;

  const Box share{left, right, top, top + panel_h, x_lo, x_hi, -0.04, 1.04};
  const Box error{left, right, bottom - panel_h, bottom, x_lo, x_hi, 0.0, 1.1 * e_hi};
  c.text(title, 0.5 * w, 0.6 * size, static_cast<float>(1.2 * size), s.text, HAlign::kCenter,
         VAlign::kTop);
  drawAxes(c, share, in, "met tolerance (share, 95% Wilson interval)", false, s);
  drawAxes(c, error, in, in.error_label + ": median (orange), p95 (blue)", true, s);
  for (const ParameterPlotLevel& l : in.levels) {
    const double x = share.px(l.x);
    c.line(x, share.py(l.met_low), x, share.py(l.met_high), s.axis, s.path_px, 0.003);
  }
  series(
      c, share, in, [](const ParameterPlotLevel& l) { return std::optional<double>(l.met_share); },
      s.goal, s);
  series(
      c, error, in, [](const ParameterPlotLevel& l) { return l.error_median; }, s.executed, s);
  series(
      c, error, in, [](const ParameterPlotLevel& l) { return l.error_p95; }, s.planned, s);
  if (in.boundary_x) {
    for (const Box* b : {&share, &error}) {
      c.line(b->px(*in.boundary_x), b->top, b->px(*in.boundary_x), b->bottom, s.contact, s.path_px,
             0.005);
    }
    c.text("boundary", share.px(*in.boundary_x), share.top + 0.3 * size, static_cast<float>(size),
           s.contact, HAlign::kLeft, VAlign::kTop);
  }
  c.text(in.parameter, 0.5 * (left + right), h - 0.4 * size, static_cast<float>(size), s.text,
         HAlign::kCenter, VAlign::kBottom);
  return scene;
}

}  // namespace parksim
