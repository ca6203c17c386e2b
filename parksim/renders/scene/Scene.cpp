#include "parksim/renders/scene/Scene.h"

#include <algorithm>

namespace parksim {

namespace {

template <class T>
void appendAll(std::vector<T>& into, const std::vector<T>& from) {
  into.insert(into.end(), from.begin(), from.end());
}

}  // namespace

void appendScene(Scene& into, const Scene& from) {
  appendAll(into.polygons, from.polygons);
  appendAll(into.boxes, from.boxes);
  appendAll(into.prisms, from.prisms);
  appendAll(into.lines, from.lines);
  appendAll(into.arrows, from.arrows);
  appendAll(into.texts, from.texts);
  if (from.focus) {
    into.focus = from.focus;
    into.focus_scale = from.focus_scale;
  }
}

std::vector<ScenePolyline> dashed(const ScenePolyline& line, double dash_m, double gap_m) {
  std::vector<ScenePolyline> dashes;
  std::vector<Eigen::Vector3d> pts = line.points;
  if (line.closed && pts.size() > 2) pts.push_back(pts.front());
  if (pts.size() < 2 || dash_m <= 0.0 || gap_m <= 0.0) {
    dashes.push_back(line);
    return dashes;
  }
  const double period = dash_m + gap_m;
  double phase = 0.0;  // distance into the current period
  ScenePolyline current{{}, line.color, line.width_px, false};
  current.points.push_back(pts.front());
  for (std::size_t i = 1; i < pts.size(); ++i) {
    Eigen::Vector3d a = pts[i - 1];
    const Eigen::Vector3d b = pts[i];
    double remaining = (b - a).norm();
    // Leftovers below a picometre are rounding, not line: they would make zero-length dashes.
    while (remaining > 1e-12) {
      const bool drawing = phase < dash_m;
      const double to_switch = drawing ? dash_m - phase : period - phase;
      if (to_switch > remaining) {
        if (drawing) current.points.push_back(b);
        phase += remaining;
        break;
      }
      // Switching exactly at a dash boundary; phase is set, not accumulated, so rounding
      // cannot leave it a hair short of the boundary forever.
      a += (b - a) * (to_switch / remaining);
      remaining -= to_switch;
      if (drawing) {
        current.points.push_back(a);
        if (current.points.size() >= 2) dashes.push_back(current);
        current.points.clear();
        phase = dash_m;
      } else {
        current.points.assign(1, a);
        phase = 0.0;
      }
    }
  }
  if (current.points.size() >= 2) dashes.push_back(current);
  return dashes;
}

ScenePolyline boxOutline(const OrientedBox& box, double z_m, Rgba8 color, float width_px) {
  ScenePolyline outline{{}, color, width_px, true};
  for (const Eigen::Vector2d& c : box.corners()) outline.points.emplace_back(c.x(), c.y(), z_m);
  return outline;
}

}  // namespace parksim
