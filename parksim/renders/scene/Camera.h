#pragma once
// Cameras: where a view looks from and how world points map to pixels. Pure math, shared by the
// renderer and by tests that need to know where something lands in an image.

#include <optional>

#include <Eigen/Core>

#include "parksim/renders/scene/Scene.h"

namespace parksim {

enum class CameraMode {
  kTopDown,      ///< orthographic, looking straight down, framing Scene::extent (the study's view)
  kPerspective,  ///< perspective from a fixed direction, framing Scene::extent
  kFollow,       ///< perspective from a fixed direction, following Scene::focus
};

struct CameraDef {
  CameraMode mode = CameraMode::kTopDown;
  double fov_y_deg = 40.0;  ///< perspective: vertical field of view, degrees
  /// Perspective: direction from the target to the camera in the ground plane, degrees
  /// counter-clockwise from +x. -90 puts the camera south of the lot, so +x points right.
  double azimuth_deg = -90.0;
  double elevation_deg = 50.0;  ///< perspective: angle above the ground plane, degrees
  /// kFollow: camera distance from the focus for a robot of the study's size, m; the scene's
  /// focus_scale (the followed robot's size in study robots) scales it.
  double follow_distance_m = 0.55;
  /// kTopDown and kPerspective: the extent fills this fraction of the image (<= 1).
  double fill = 0.98;
};

/// A camera placed for one image size. Pixel coordinates run from the top-left corner of the
/// image, x right and y down; pixel (i, j) covers [i, i+1) x [j, j+1).
struct Camera {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();  ///< camera position, m
  int width_px = 1;
  int height_px = 1;
  bool perspective = false;

  Eigen::Matrix4d viewProjection() const { return projection * view; }
  /// Pixel position of a world point; unset when it lies behind a perspective camera.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world) const;

  friend bool operator==(const Camera&, const Camera&) = default;
};

/// Places a camera for `scene` (its extent and focus) in an image of the given size.
Camera makeCamera(const CameraDef& def, const Scene& scene, int width_px, int height_px);

}  // namespace parksim
