#pragma once
// Drawing in pixel coordinates (from the top-left, y down) onto a Scene whose world units are
// pixels (extent 0..width x 0..height, y up), for the statistical plots (BoxPlot.h,
// SuccessMatrix.h). Draw the Scene with the top-down camera at width x height, camera fill 1.

#include <string>
#include <utility>

#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

class PlotCanvas {
 public:
  /// Starts `scene` as a white canvas of width x height pixels.
  PlotCanvas(Scene& scene, int width_px, int height_px) : scene_(scene), height_(height_px) {
    scene_.background = rgb(255, 255, 255);
    scene_.extent = {0.0, 0.0, static_cast<double>(width_px), static_cast<double>(height_px)};
  }

  Eigen::Vector3d at(double x_px, double y_px, double z = 0.0) const {
    return {x_px, height_ - y_px, z};
  }

  void text(std::string s, double x, double y, float size_px, Rgba8 color, HAlign h, VAlign v) {
    scene_.texts.push_back(
        {std::move(s), at(x, y), Eigen::Vector2d::Zero(), size_px, color, {0, 0, 0, 0}, h, v});
  }

  /// Later layers (higher z) draw over earlier ones.
  void line(double x0, double y0, double x1, double y1, Rgba8 color, float width_px, double z) {
    scene_.lines.push_back({{at(x0, y0, z), at(x1, y1, z)}, color, width_px, false});
  }

  void fillRect(double left, double top, double right, double bottom, Rgba8 color, double z) {
    scene_.polygons.push_back({{at(left, bottom).head<2>(), at(right, bottom).head<2>(),
                                at(right, top).head<2>(), at(left, top).head<2>()},
                               z,
                               color});
  }

  void outlineRect(double left, double top, double right, double bottom, Rgba8 color,
                   float width_px, double z) {
    scene_.lines.push_back(
        {{at(left, top, z), at(right, top, z), at(right, bottom, z), at(left, bottom, z)},
         color,
         width_px,
         true});
  }

 private:
  Scene& scene_;
  double height_;
};

}  // namespace parksim
