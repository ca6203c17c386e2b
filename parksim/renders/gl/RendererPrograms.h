#pragma once
// Internal to parksim_render (not installed): the renderer's shader programs, compiled and linked
// once per renderer, and the uniforms it sets per frame.
//
// Separate programs rather than branches on uniforms: llvmpipe's shaders run both sides of a
// branch under a mask, so an unused texture fetch or lighting term would cost every fragment.

#include "parksim/renders/gl/GlFunctions.h"

namespace parksim {

struct RendererPrograms {
  GLuint flat = 0;   ///< meshes in their exact colours (top views)
  GLuint lit = 0;    ///< meshes under one directional light (perspective views)
  GLuint solid = 0;  ///< lines and solid overlay areas, with coverage fading at line edges
  GLuint text = 0;   ///< glyphs from a font atlas bound to texture unit 0
  GLint flat_view_proj = -1;
  GLint lit_view_proj = -1;
  GLint light = -1;      ///< lit: direction towards the light
  GLint ambient = -1;    ///< lit: share of the colour independent of the light
  GLint up_factor = -1;  ///< lit: the factor an upward face gets (it is divided out)

  /// Compiles and links all four. Throws Error with the GL's log when one fails (after
  /// releasing what was made).
  void create(const GlFunctions& gl);
  void destroy(const GlFunctions& gl);
};

/// Throws Error "renderer: OpenGL error 0x0500 in WHERE" when the GL has recorded an error.
void checkGl(const GlFunctions& gl, const char* where);

}  // namespace parksim
