#pragma once
// What to draw, apart from how: a draw list in world coordinates (metres, z up) that the
// renderer turns into pixels. Building a Scene needs no OpenGL, so its content is unit-tested
// on its own (MuJoCo's mjvScene / mjr_render split).
//
// Draw order: polygons, then boxes and prisms, then lines, then arrows, then text. Within each kind
// the list order is kept, so a later item wins over an earlier one at the same height. The depth
// test still hides lines and polygons below the top of a box.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/renders/image/Color.h"

namespace parksim {

/// An axis-aligned rectangle of the ground plane, m.
struct Extent2 {
  double x_min = 0.0;
  double y_min = 0.0;
  double x_max = 1.0;
  double y_max = 1.0;

  double width() const { return x_max - x_min; }
  double height() const { return y_max - y_min; }
  Eigen::Vector2d center() const { return {0.5 * (x_min + x_max), 0.5 * (y_min + y_max)}; }

  friend bool operator==(const Extent2&, const Extent2&) = default;
};

/// A box standing on its footprint: obstacles, the robot's body and wheels.
struct SceneBox {
  OrientedBox footprint;  ///< in the ground plane, m
  double z_min_m = 0.0;   ///< bottom face height, m
  double height_m = 0.1;  ///< m
  Rgba8 color;

  friend bool operator==(const SceneBox&, const SceneBox&) = default;
};

/// A convex polygon extruded vertically: round and polygonal obstacles (a circle is drawn as a
/// many-sided polygon on it).
struct ScenePrism {
  std::vector<Eigen::Vector2d> footprint;  ///< convex, counter-clockwise, m
  double z_min_m = 0.0;                    ///< bottom face height, m
  double height_m = 0.1;                   ///< m
  Rgba8 color;

  friend bool operator==(const ScenePrism&, const ScenePrism&) = default;
};

/// A filled convex polygon lying in the horizontal plane z = z_m (ground, C-space slices).
struct ScenePolygon {
  std::vector<Eigen::Vector2d> points;  ///< convex, either winding, m
  double z_m = 0.0;
  Rgba8 color;

  friend bool operator==(const ScenePolygon&, const ScenePolygon&) = default;
};

/// A line of constant on-screen width through world points (paths, tree edges, outlines).
struct ScenePolyline {
  std::vector<Eigen::Vector3d> points;  ///< m
  Rgba8 color;
  float width_px = 2.0f;  ///< on-screen width, pixels
  bool closed = false;    ///< joins the last point back to the first

  friend bool operator==(const ScenePolyline&, const ScenePolyline&) = default;
};

/// An arrow lying flat at height z_m: a shaft from the pose along its heading and a filled head
/// at the far end (the study's start and goal markers).
struct SceneArrow {
  Pose2 pose;             ///< tail position and direction
  double length_m = 0.1;  ///< tail to tip, m
  double head_m = 0.03;   ///< head length (and width), m
  double z_m = 0.0;
  Rgba8 color;
  float width_px = 3.0f;  ///< shaft width, pixels

  friend bool operator==(const SceneArrow&, const SceneArrow&) = default;
};

enum class HAlign { kLeft, kCenter, kRight };
enum class VAlign { kTop, kMiddle, kBottom };

/// A line of UTF-8 text, either fixed on the screen or attached to a world point.
struct SceneText {
  std::string text;
  /// Set: the text is anchored at this world point, m. Unset: at `screen_px`.
  std::optional<Eigen::Vector3d> world;
  Eigen::Vector2d screen_px = Eigen::Vector2d::Zero();  ///< from the top-left corner, y down
  float size_px = 16.0f;                                ///< pixel height of the font
  Rgba8 color;
  Rgba8 background{0, 0, 0, 0};  ///< box behind the text; alpha 0 draws none
  HAlign h_align = HAlign::kLeft;
  VAlign v_align = VAlign::kTop;

  /// Text anchored at a world point, with no background box.
  static SceneText worldLabel(std::string text, const Eigen::Vector3d& world, float size_px,
                              Rgba8 color, HAlign h_align, VAlign v_align) {
    return {std::move(text), world,  Eigen::Vector2d::Zero(), size_px, color, {0, 0, 0, 0},
            h_align,         v_align};
  }

  friend bool operator==(const SceneText&, const SceneText&) = default;
};

struct Scene {
  Rgba8 background{255, 255, 255, 255};
  /// The ground rectangle a top-down camera frames and a fixed 3D camera looks at, m.
  Extent2 extent;
  /// Height up to which a fixed 3D camera keeps the volume above the extent in view, m (the
  /// C-space stack rises above the lot).
  double extent_top_m = 0.0;
  /// What a following camera looks at (the robot's reference point), m.
  std::optional<Eigen::Vector3d> focus;
  /// The size of what the focus follows in study robots (RobotDef::sizeScale): a following
  /// camera's distance (CameraDef::follow_distance_m) is in proportion to it.
  double focus_scale = 1.0;
  std::vector<ScenePolygon> polygons;
  std::vector<SceneBox> boxes;
  std::vector<ScenePrism> prisms;
  std::vector<ScenePolyline> lines;
  std::vector<SceneArrow> arrows;
  std::vector<SceneText> texts;

  /// Equal scenes draw equal images through the same camera: a renderer keeps a backdrop's
  /// pixels while the backdrop stays equal (Renderer::renderInto).
  friend bool operator==(const Scene&, const Scene&) = default;
};

/// Appends `from`'s items after `into`'s, kind by kind: the items of both in one scene, drawn
/// in its order (kinds first, then list order). `from`'s focus (and its scale) replaces `into`'s
/// when set; background and extent are kept.
void appendScene(Scene& into, const Scene& from);

/// Splits a polyline into dashes of `dash_m` separated by gaps of `gap_m` (lengths in the
/// world, so dashes keep their size along a curve). Returns the dashes as separate polylines;
/// the line itself when either length is not positive.
std::vector<ScenePolyline> dashed(const ScenePolyline& line, double dash_m, double gap_m);

/// The four corners of `box` at height z, as a closed outline.
ScenePolyline boxOutline(const OrientedBox& box, double z_m, Rgba8 color, float width_px);

}  // namespace parksim
