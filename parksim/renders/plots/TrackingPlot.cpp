#include "parksim/renders/plots/TrackingPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Csv.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

std::vector<double> niceTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || target < 1) return ticks;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * mag;
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  }
  // Multiples of the step by integer count, so no rounding accumulates along the axis.
  const double first = std::ceil(lo / step - 1e-9);
  for (double k = first; k * step <= hi + 1e-9 * step; k += 1.0) ticks.push_back(k * step);
  return ticks;
}

std::string formatTick(double value, double step) {
  const int decimals =
      step > 0.0 ? std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9))) : 1;
  // A value that rounds to zero prints as "0", never "-0.0".
  const double unit = std::pow(10.0, -decimals);
  if (std::abs(value) < 0.5 * unit) value = 0.0;
  return formatFixed(value, decimals);
}

namespace {

struct Panel {
  double left, right, top, bottom;  // pixels from the top-left
  double x_lo, x_hi, y_lo, y_hi;    // data range
};

class PlotBuilder {
 public:
  PlotBuilder(Scene& scene, int height, const SceneStyle& style)
      : scene_(scene), height_(height), style_(style) {}

  Eigen::Vector3d at(double x_px, double y_px, double z = 0.0) const {
    return {x_px, height_ - y_px, z};
  }

  void text(const std::string& s, double x, double y, float size, HAlign h, VAlign v) {
    scene_.texts.push_back(
        {s, at(x, y), Eigen::Vector2d::Zero(), size, style_.text, {0, 0, 0, 0}, h, v});
  }

  void line(double x0, double y0, double x1, double y1, Rgba8 color, float width, double z) {
    scene_.lines.push_back({{at(x0, y0, z), at(x1, y1, z)}, color, width, false});
  }

  void panel(const Panel& p, const std::vector<double>& t, const std::vector<double>& values,
             const std::string& label, Rgba8 color, bool time_labels) {
    auto px = [&](double x) {
      return p.left + (x - p.x_lo) / (p.x_hi - p.x_lo) * (p.right - p.left);
    };
    auto py = [&](double y) {
      return p.bottom - (y - p.y_lo) / (p.y_hi - p.y_lo) * (p.bottom - p.top);
    };
    const float size = style_.text_px;
    const float tick_len = 0.4f * size;
    scene_.polygons.push_back({{at(p.left, p.bottom).head<2>(), at(p.right, p.bottom).head<2>(),
                                at(p.right, p.top).head<2>(), at(p.left, p.top).head<2>()},
                               0.0,
                               rgb(255, 255, 255)});
    const std::vector<double> xt = niceTicks(p.x_lo, p.x_hi, 8);
    const std::vector<double> yt = niceTicks(p.y_lo, p.y_hi, 5);
    for (double x : xt) {
      line(px(x), p.top, px(x), p.bottom, style_.grid, style_.grid_px, 0.001);
      line(px(x), p.bottom, px(x), p.bottom + tick_len, style_.axis, style_.grid_px, 0.003);
      if (time_labels && xt.size() > 1) {
        text(formatTick(x, xt[1] - xt[0]), px(x), p.bottom + 1.6 * tick_len, size, HAlign::kCenter,
             VAlign::kTop);
      }
    }
    for (double y : yt) {
      line(p.left, py(y), p.right, py(y), y == 0.0 ? style_.axis : style_.grid, style_.grid_px,
           0.001);
      line(p.left - tick_len, py(y), p.left, py(y), style_.axis, style_.grid_px, 0.003);
      if (yt.size() > 1) {
        text(formatTick(y, yt[1] - yt[0]), p.left - 1.6 * tick_len, py(y), size, HAlign::kRight,
             VAlign::kMiddle);
      }
    }
    ScenePolyline frame{{at(p.left, p.top, 0.003), at(p.right, p.top, 0.003),
                         at(p.right, p.bottom, 0.003), at(p.left, p.bottom, 0.003)},
                        style_.axis,
                        style_.border_px,
                        true};
    scene_.lines.push_back(frame);
    ScenePolyline data{{}, color, style_.path_px, false};
    data.points.reserve(t.size());
    for (std::size_t i = 0; i < t.size(); ++i)
      data.points.push_back(at(px(t[i]), py(values[i]), 0.002));
    if (data.points.size() >= 2) scene_.lines.push_back(std::move(data));
    text(label, p.left, p.top - 0.5 * size, size, HAlign::kLeft, VAlign::kBottom);
  }

 private:
  Scene& scene_;
  double height_;
  const SceneStyle& style_;
};

std::pair<double, double> paddedRange(const std::vector<double>& v, bool include_zero,
                                      double min_span) {
  double lo = v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
  double hi = v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  if (include_zero) {
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
  }
  if (hi - lo < min_span) {
    const double mid = 0.5 * (lo + hi);
    lo = lo >= 0.0 && include_zero ? 0.0 : mid - 0.5 * min_span;
    hi = lo + min_span;
  }
  const double pad = 0.08 * (hi - lo);
  return {lo < 0.0 ? lo - pad : lo, hi + pad};
}

}  // namespace

Scene buildTrackingPlot(const TrackingSeries& series, const std::string& title, int width_px,
                        int height_px, const SceneStyle& style) {
  const std::size_t n = series.t_s.size();
  if (series.position_error_m.size() != n || series.heading_error_rad.size() != n) {
    throw Error("tracking plot: t, position error and heading error differ in length");
  }
  Scene scene;
  scene.background = rgb(255, 255, 255);
  scene.extent = {0.0, 0.0, static_cast<double>(width_px), static_cast<double>(height_px)};
  const double w = width_px;
  const double h = height_px;
  const double size = style.text_px;
  const double left = 6.0 * size;
  const double right = w - 1.5 * size;
  const double top = 3.6 * size;
  const double bottom = h - 3.4 * size;
  const double gap = 3.4 * size;
  const double panel_h = std::max(10.0, 0.5 * (bottom - top - gap));

  std::vector<double> pos_mm(n);
  std::vector<double> head_deg(n);
  for (std::size_t i = 0; i < n; ++i) {
    pos_mm[i] = 1000.0 * series.position_error_m[i];
    head_deg[i] = radToDeg(series.heading_error_rad[i]);
  }
  double t_lo = n > 0 ? series.t_s.front() : 0.0;
  double t_hi = n > 0 ? series.t_s.back() : 1.0;
  if (!(t_hi > t_lo)) t_hi = t_lo + 1.0;
  const auto [p_lo, p_hi] = paddedRange(pos_mm, true, 1.0);
  const auto [h_lo, h_hi] = paddedRange(head_deg, true, 1.0);

  PlotBuilder plot(scene, height_px, style);
  plot.text(title, 0.5 * w, 0.6 * size, static_cast<float>(1.2 * size), HAlign::kCenter,
            VAlign::kTop);
  plot.panel({left, right, top, top + panel_h, t_lo, t_hi, p_lo, p_hi}, series.t_s, pos_mm,
             "position error (mm)", style.executed, false);
  plot.panel({left, right, bottom - panel_h, bottom, t_lo, t_hi, h_lo, h_hi}, series.t_s, head_deg,
             "heading error (\u00b0)", style.planned, true);
  plot.text("time (s)", 0.5 * (left + right), h - 0.4 * size, static_cast<float>(size),
            HAlign::kCenter, VAlign::kBottom);
  return scene;
}

TrackingSeries readTrackingCsv(const std::string& path) {
  const CsvTable csv = readCsvFile(path);
  const auto t_col = csv.findColumn(kTrackingTimeNames);
  const auto p_col = csv.findColumn(kTrackingPositionNames);
  const auto h_rad = csv.findColumn(kTrackingHeadingRadNames);
  const auto h_deg = csv.findColumn(kTrackingHeadingDegNames);
  if (!t_col || !p_col || (!h_rad && !h_deg)) {
    std::string header;
    for (const std::string& name : csv.header()) header += (header.empty() ? "" : ",") + name;
    throw Error(path +
                ":1: needs columns t, pos_err and heading_err (or their longer names), got '" +
                header + "'");
  }
  const std::size_t h_col = h_rad ? *h_rad : *h_deg;
  const double h_scale = h_rad ? 1.0 : kPi / 180.0;
  // A plot of nothing, or of time running backwards (rows out of order, two files joined),
  // would be drawn without a word.
  if (csv.rows().empty()) throw Error(path + ": no rows (the header alone)");
  TrackingSeries series;
  for (const CsvTable::Row& row : csv.rows()) {
    const double t = csv.number(row, *t_col);
    if (!series.t_s.empty() && !(t > series.t_s.back())) {
      throw Error(path + ":" + std::to_string(row.line) + ": column '" + csv.header()[*t_col] +
                  "': time does not increase");
    }
    series.t_s.push_back(t);
    series.position_error_m.push_back(csv.number(row, *p_col));
    series.heading_error_rad.push_back(csv.number(row, h_col) * h_scale);
  }
  return series;
}

}  // namespace parksim
