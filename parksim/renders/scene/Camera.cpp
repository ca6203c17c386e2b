#include "parksim/renders/scene/Camera.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                       const Eigen::Vector3d& up) {
  const Eigen::Vector3d f = (target - eye).normalized();
  const Eigen::Vector3d s = f.cross(up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d orthographic(double l, double r, double b, double t, double n, double f) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = 2.0 / (r - l);
  m(1, 1) = 2.0 / (t - b);
  m(2, 2) = -2.0 / (f - n);
  m(0, 3) = -(r + l) / (r - l);
  m(1, 3) = -(t + b) / (t - b);
  m(2, 3) = -(f + n) / (f - n);
  return m;
}

Eigen::Matrix4d perspectiveMatrix(double fov_y_rad, double aspect, double n, double f) {
  const double t = 1.0 / std::tan(0.5 * fov_y_rad);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = -(f + n) / (f - n);
  m(2, 3) = -2.0 * f * n / (f - n);
  m(3, 2) = -1.0;
  return m;
}

}  // namespace

std::optional<Eigen::Vector2d> Camera::project(const Eigen::Vector3d& world) const {
  const Eigen::Vector4d clip = viewProjection() * world.homogeneous();
  if (clip.w() <= 1e-12) return std::nullopt;
  const double nx = clip.x() / clip.w();
  const double ny = clip.y() / clip.w();
  return Eigen::Vector2d(0.5 * (nx + 1.0) * width_px, 0.5 * (1.0 - ny) * height_px);
}

Camera makeCamera(const CameraDef& def, const Scene& scene, int width_px, int height_px) {
  if (width_px <= 0 || height_px <= 0) throw Error("camera: image size must be positive");
  Camera cam;
  cam.width_px = width_px;
  cam.height_px = height_px;
  const double aspect = static_cast<double>(width_px) / height_px;
  const Extent2& e = scene.extent;
  const double fill = std::clamp(def.fill, 0.05, 1.0);

  if (def.mode == CameraMode::kTopDown) {
    // Square pixels: the extent's longer side (relative to the image) sets the scale.
    const double half_w = 0.5 * std::max(e.width(), e.height() * aspect) / fill;
    const double half_h = half_w / aspect;
    const Eigen::Vector2d c = e.center();
    const double top = 10.0;  // camera height, m; far above anything a lot holds
    cam.eye = {c.x(), c.y(), top};
    cam.view = lookAt(cam.eye, {c.x(), c.y(), 0.0}, Eigen::Vector3d::UnitY());
    cam.projection = orthographic(-half_w, half_w, -half_h, half_h, 0.0, 2.0 * top);
    return cam;
  }

  const double fov_y = degToRad(std::clamp(def.fov_y_deg, 5.0, 150.0));
  const double fov_x = 2.0 * std::atan(std::tan(0.5 * fov_y) * aspect);
  const double az = degToRad(def.azimuth_deg);
  const double el = degToRad(std::clamp(def.elevation_deg, 1.0, 89.0));
  const Eigen::Vector3d dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  Eigen::Vector3d target;
  double distance = 0.0;
  double radius = 0.0;  // of what must stay between the clip planes, m
  if (def.mode == CameraMode::kFollow && scene.focus) {
    target = *scene.focus;
    distance = std::max(def.follow_distance_m * scene.focus_scale, 0.01);
    radius = std::hypot(e.width(), e.height()) + distance;
  } else {
    const double top = std::max(scene.extent_top_m, 0.0);
    target = {e.center().x(), e.center().y(), 0.5 * top};
    radius = 0.5 * std::sqrt(e.width() * e.width() + e.height() * e.height() + top * top);
    // The nearest distance from which every corner of the extent's volume is in view: a corner
    // at lateral offsets (x, y) and offset a towards the camera needs |x| <= tan(fov_x / 2)
    // (distance - a), and likewise for y.
    const Eigen::Vector3d f = -dir;
    const Eigen::Vector3d side = f.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d up = side.cross(f);
    const double tx = std::tan(0.5 * fov_x) * fill;
    const double ty = std::tan(0.5 * fov_y) * fill;
    for (double x : {e.x_min, e.x_max}) {
      for (double y : {e.y_min, e.y_max}) {
        for (double z : {0.0, top}) {
          const Eigen::Vector3d rel = Eigen::Vector3d(x, y, z) - target;
          const double a = rel.dot(dir);
          distance = std::max(
              {distance, std::abs(rel.dot(side)) / tx + a, std::abs(rel.dot(up)) / ty + a});
        }
      }
    }
  }
  cam.eye = target + distance * dir;
  cam.perspective = true;
  cam.view = lookAt(cam.eye, target, Eigen::Vector3d::UnitZ());
  const double near_m = std::max(0.005, 0.02 * distance);
  const double far_m = distance + 2.0 * radius + 1.0;
  cam.projection = perspectiveMatrix(fov_y, aspect, near_m, far_m);
  return cam;
}

}  // namespace parksim
