#pragma once
// What the GL draws for one image, as plain data: vertex arrays in draw batches, the clears that
// come first and the uniforms the shaders take. Built from a Scene and a Camera without any GL
// (SceneTessellator.h), uploaded and drawn by the Renderer: MuJoCo's split between its
// visualiser (mjv_updateScene) and its renderer (mjr_render), one step further down.
//
// Draw order, which the renderer keeps: clear (with the ground rectangle), the meshes (opaque,
// then translucent), the lines (opaque, then translucent; depth-tested, writing no depth), then
// without the depth test the text boxes and the glyph batches, smallest font first. Within a
// batch, vertices are drawn in order, three per triangle.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "parksim/renders/image/Color.h"

namespace parksim {

/// A vertex of a lit or flat mesh: world position (m), face normal, colour.
struct MeshVertex {
  float pos[3];
  float normal[3];
  std::uint8_t color[4];
};

/// A vertex of a line ribbon, a text box or a glyph: positions already in clip space, so lines
/// keep a width in pixels in every view.
struct OverlayVertex {
  float pos[4];
  /// Glyphs: atlas coordinates. Lines: u is the signed distance across the ribbon and v its half
  /// width, pixels; the shader fades coverage over the outermost pixel (a huge v never fades:
  /// kSolidHalfWidth).
  float uv[2];
  std::uint8_t color[4];
};

/// Half width given to solid areas drawn by the line shader: they never fade.
inline constexpr float kSolidHalfWidth = 1e6f;

/// A rectangle of pixels: x, y from the image's top-left corner, width and height.
struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;

  friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

/// Glyph quads of one font size, drawn with that size's atlas (FontCache).
struct GlyphBatch {
  int font_px = 0;  ///< the atlas's pixel height (FontCache::key)
  std::vector<OverlayVertex> vertices;
};

struct DrawList {
  int width_px = 0;
  int height_px = 0;
  /// Colour the whole image is cleared to: the ground's when `ground` is set, else the
  /// background.
  Rgba8 clear_color;
  /// The scene's background, cleared back into the margins around `ground`.
  Rgba8 background;
  /// A top view's ground rectangle, filled by the clear instead of drawn (it covers exactly the
  /// pixels whose centres lie inside it, as rasterizing it would). Unset: nothing skipped.
  std::optional<PixelRect> ground;

  /// Meshes: lit (perspective views) or flat (top views, exact colours).
  bool lit = false;
  /// World to clip space, with y flipped so that framebuffer row 0 is the image's top row.
  Eigen::Matrix4f view_proj = Eigen::Matrix4f::Identity();
  std::array<float, 3> light{0.0f, 0.0f, 1.0f};  ///< lit: unit direction towards the light
  float ambient = 1.0f;                          ///< lit: share independent of the light
  float up_factor = 1.0f;                        ///< lit: an upward face's factor, divided out

  /// Opaque and translucent geometry go to separate batches: blending makes llvmpipe read the
  /// framebuffer back for every fragment, so only what needs it pays for it.
  std::vector<MeshVertex> mesh;
  std::vector<MeshVertex> mesh_blend;
  std::vector<OverlayVertex> lines;
  std::vector<OverlayVertex> lines_blend;
  std::vector<OverlayVertex> text_boxes;  ///< solid boxes behind text (blended)
  std::vector<GlyphBatch> glyphs;         ///< by font size, ascending

  /// Empties every batch, keeping the memory for the next image.
  void clear();
  /// The margins around `ground` that are cleared back to the background: above, below, left
  /// and right of it (all empty without a ground; some may be empty with one).
  std::array<PixelRect, 4> groundMargins() const;
  /// Triangles in all batches.
  std::size_t triangleCount() const;
};

}  // namespace parksim
