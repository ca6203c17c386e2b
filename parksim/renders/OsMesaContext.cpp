#include "parksim/renders/OsMesaContext.h"

#include <GL/osmesa.h>
// osmesa.h pulls in the compatibility GL header; core-profile entry points come from glext.h
// (libOSMesa exports them, GL_GLEXT_PROTOTYPES is set for this library).
#include <GL/glext.h>

#include <array>
#include <string>

#include "parksim/core/Error.h"

namespace parksim::detail {

namespace {

class OsMesaContext final : public OffscreenContext {
 public:
  explicit OsMesaContext(const ContextDef& def) {
    const std::array<int, 11> attribs = {OSMESA_FORMAT,
                                         OSMESA_RGBA,
                                         OSMESA_DEPTH_BITS,
                                         0,
                                         OSMESA_PROFILE,
                                         OSMESA_CORE_PROFILE,
                                         OSMESA_CONTEXT_MAJOR_VERSION,
                                         def.gl_major,
                                         OSMESA_CONTEXT_MINOR_VERSION,
                                         def.gl_minor,
                                         0};
    ctx_ = OSMesaCreateContextAttribs(attribs.data(), nullptr);
    if (ctx_ == nullptr) {
      throw Error("OSMesa: cannot create an OpenGL " + std::to_string(def.gl_major) + "." +
                  std::to_string(def.gl_minor) + " core context");
    }
    makeCurrent();
    auto str = [](GLenum name) {
      const auto* s = reinterpret_cast<const char*>(glGetString(name));
      return std::string(s != nullptr ? s : "?");
    };
    description_ = "OSMesa: " + str(GL_VERSION) + ", " + str(GL_RENDERER);
  }

  ~OsMesaContext() override {
    if (OSMesaGetCurrentContext() == ctx_)
      OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx_);
  }

  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void makeCurrent() override {
    // Drawing goes to the caller's framebuffer objects; the window-system buffer OSMesa
    // insists on is a single pixel.
    if (!OSMesaMakeCurrent(ctx_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw Error("OSMesa: cannot make the context current");
    }
  }

  bool isCurrent() const override { return OSMesaGetCurrentContext() == ctx_; }

  std::string description() const override { return description_; }

 private:
  OSMesaContext ctx_ = nullptr;
  std::array<unsigned char, 4> pixel_{};
  std::string description_;
};

}  // namespace

std::unique_ptr<OffscreenContext> createOsMesaContext(const ContextDef& def) {
  return std::make_unique<OsMesaContext>(def);
}

}  // namespace parksim::detail
