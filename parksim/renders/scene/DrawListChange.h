#pragma once
// Where the pixels of two draw lists differ, found from the lists alone: a film's front (the robot,
// its driven path, the HUD) changes in a few places from one frame to the next, and the renderer
// then restores, draws and reads back only those (Renderer::renderChanges), not the whole image.
//
// Two lists drawn over the same pixels give the same pixel wherever the triangles covering it
// are the same, in the same order. So the triangles both lists share in order (a common
// subsequence, batch by batch) are left out, and only the others' screen rectangles count.

#include <vector>

#include "parksim/renders/scene/DrawList.h"

namespace parksim {

/// How changedRects looks and merges. The defaults suit a film's frames.
struct DrawListChangeDef {
  /// At most this many rectangles; nearest ones are merged beyond it. Each costs the renderer a
  /// copy, a scissored draw of the whole list and a read-back.
  int max_rects = 4;  // 1 to 64
  /// Triangles looked ahead for one that was left out or put in (a path that grew, a glyph
  /// that changed width); a larger window finds more in common and costs more on a mismatch.
  int lookahead = 32;  // 0 to 1024
  /// Pixels added on every side of a triangle's bounds: a rasterizer snaps vertices to its
  /// sub-pixel grid and a line's soft edge lies on its outermost pixel.
  int margin_px = 2;  // 0 to 64
};

/// Rectangles (image pixels, from the top-left corner) outside which `before` and `after`,
/// each drawn over the same pixels, give the same image. Empty: the images are equal. The whole
/// image when the lists differ in size or uniforms (camera, light), or when a changed vertex
/// lies behind the camera. The rectangles neither overlap nor touch.
std::vector<PixelRect> changedRects(const DrawList& before, const DrawList& after,
                                    const DrawListChangeDef& def = {});

}  // namespace parksim
