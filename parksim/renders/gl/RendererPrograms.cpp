#include "parksim/renders/gl/RendererPrograms.h"

#include <cstdio>
#include <string>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

constexpr const char* kMeshVs = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;
uniform mat4 u_view_proj;
out vec3 v_normal;
out vec4 v_color;
void main() {
  gl_Position = u_view_proj * vec4(a_pos, 1.0);
  v_normal = a_normal;
  v_color = a_color;
}
)";

constexpr const char* kFlatFs = R"(#version 330 core
in vec3 v_normal;
in vec4 v_color;
out vec4 o_color;
void main() { o_color = v_color; }
)";

// The light is scaled so that an upward face gets exactly its colour (factor 1).
constexpr const char* kLitFs = R"(#version 330 core
in vec3 v_normal;
in vec4 v_color;
uniform vec3 u_light;
uniform float u_ambient;
uniform float u_up_factor;
out vec4 o_color;
void main() {
  float d = max(dot(normalize(v_normal), u_light), 0.0);
  float f = min((u_ambient + (1.0 - u_ambient) * d) / u_up_factor, 1.0);
  o_color = vec4(v_color.rgb * f, v_color.a);
}
)";

constexpr const char* kOverlayVs = R"(#version 330 core
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_color;
out vec2 v_uv;
out vec4 v_color;
void main() {
  // Rows are read back top first: flip y so the image needs no flip on the CPU.
  gl_Position = vec4(a_pos.x, -a_pos.y, a_pos.z, a_pos.w);
  v_uv = a_uv;
  v_color = a_color;
}
)";

// v_uv.x: distance from a line's centre, pixels; v_uv.y: the line's half width. Coverage fades
// over the outermost pixel, which anti-aliases lines when there is no multisampling. Solid
// areas pass a huge half width.
constexpr const char* kSolidFs = R"(#version 330 core
in vec2 v_uv;
in vec4 v_color;
out vec4 o_color;
void main() {
  float coverage = clamp(v_uv.y + 0.5 - abs(v_uv.x), 0.0, 1.0);
  o_color = vec4(v_color.rgb, v_color.a * coverage);
}
)";

constexpr const char* kTextFs = R"(#version 330 core
in vec2 v_uv;
in vec4 v_color;
uniform sampler2D u_atlas;
out vec4 o_color;
void main() { o_color = vec4(v_color.rgb, v_color.a * texture(u_atlas, v_uv).r); }
)";

GLuint compileShader(const GlFunctions& gl, GLenum type, const char* source) {
  const GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[1024] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl.DeleteShader(shader);
    throw Error(std::string("renderer: shader does not compile: ") + log);
  }
  return shader;
}

GLuint linkProgram(const GlFunctions& gl, const char* vs, const char* fs) {
  const GLuint v = compileShader(gl, GL_VERTEX_SHADER, vs);
  GLuint f = 0;
  try {
    f = compileShader(gl, GL_FRAGMENT_SHADER, fs);
  } catch (...) {
    gl.DeleteShader(v);
    throw;
  }
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, v);
  gl.AttachShader(program, f);
  gl.LinkProgram(program);
  gl.DeleteShader(v);
  gl.DeleteShader(f);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[1024] = {};
    gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
    gl.DeleteProgram(program);
    throw Error(std::string("renderer: shader program does not link: ") + log);
  }
  return program;
}

}  // namespace

void RendererPrograms::create(const GlFunctions& gl) {
  try {
    flat = linkProgram(gl, kMeshVs, kFlatFs);
    lit = linkProgram(gl, kMeshVs, kLitFs);
    solid = linkProgram(gl, kOverlayVs, kSolidFs);
    text = linkProgram(gl, kOverlayVs, kTextFs);
  } catch (...) {
    destroy(gl);
    throw;
  }
  flat_view_proj = gl.GetUniformLocation(flat, "u_view_proj");
  lit_view_proj = gl.GetUniformLocation(lit, "u_view_proj");
  light = gl.GetUniformLocation(lit, "u_light");
  ambient = gl.GetUniformLocation(lit, "u_ambient");
  up_factor = gl.GetUniformLocation(lit, "u_up_factor");
  gl.UseProgram(text);
  gl.Uniform1i(gl.GetUniformLocation(text, "u_atlas"), 0);
}

void RendererPrograms::destroy(const GlFunctions& gl) {
  for (GLuint* program : {&flat, &lit, &solid, &text}) {
    gl.DeleteProgram(*program);  // 0 is ignored
    *program = 0;
  }
}

void checkGl(const GlFunctions& gl, const char* where) {
  const GLenum err = gl.GetError();
  if (err != GL_NO_ERROR) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "renderer: OpenGL error 0x%04x in %s", err, where);
    throw Error(buf);
  }
}

}  // namespace parksim
