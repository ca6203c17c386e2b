#include "parksim/renders/gl/OffscreenContext.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "RenderTestUtil.h"
#include "parksim/core/io/Error.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/gl/GlFunctions.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/plots/Figures.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "parksim/renders/scene/SceneTessellator.h"
#include "parksim/renders/text/FontLookup.h"
#include "tests/support/LoadedLibraries.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace offscreen_context_test {

// Sets (or unsets) PARKSIM_GL_BACKEND for one test and puts the old value back.
class BackendEnv {
 public:
  explicit BackendEnv(const char* value) {
    if (const char* old = std::getenv(kName)) old_ = old;
    if (value != nullptr) {
      ::setenv(kName, value, 1);
    } else {
      ::unsetenv(kName);
    }
  }
  ~BackendEnv() {
    if (old_) {
      ::setenv(kName, old_->c_str(), 1);
    } else {
      ::unsetenv(kName);
    }
  }
  BackendEnv(const BackendEnv&) = delete;
  BackendEnv& operator=(const BackendEnv&) = delete;

 private:
  static constexpr const char* kName = "PARKSIM_GL_BACKEND";
  std::optional<std::string> old_;
};

TEST(OffscreenContextTest, AutoPicksEgl) {
  const BackendEnv env(nullptr);
  const auto context = createOffscreenContext();
  EXPECT_EQ(context->backend(), ContextBackend::kEgl);
  EXPECT_TRUE(context->isCurrent());
  // Mesa's software device, as OSMesa draws: the images below depend on it.
  EXPECT_NE(context->description().find("EGL (device: software)"), std::string::npos)
      << context->description();
  EXPECT_NE(context->description().find("llvmpipe"), std::string::npos) << context->description();
}

TEST(OffscreenContextTest, EnvironmentChoosesWhenTheDefinitionDoesNot) {
  if (!contextBackendBuilt(ContextBackend::kOsMesa)) GTEST_SKIP() << "built without OSMesa";
  const BackendEnv env("osmesa");
  EXPECT_EQ(createOffscreenContext()->backend(), ContextBackend::kOsMesa);
  ContextDef def;
  def.backend = ContextBackend::kEgl;  // an explicit choice wins over the environment
  EXPECT_EQ(createOffscreenContext(def)->backend(), ContextBackend::kEgl);
}

TEST(OffscreenContextTest, BadEnvironmentValueIsNamed) {
  const BackendEnv env("vulkan");
  try {
    createOffscreenContext();
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "PARKSIM_GL_BACKEND: unknown OpenGL backend 'vulkan' (auto, egl or osmesa)");
  }
}

TEST(OffscreenContextTest, BackendNamesRoundTrip) {
  for (ContextBackend b : {ContextBackend::kAuto, ContextBackend::kEgl, ContextBackend::kOsMesa}) {
    EXPECT_EQ(contextBackendFromString(toString(b)), b);
  }
  EXPECT_THROW(contextBackendFromString("EGL"), Error);
  EXPECT_THROW(contextBackendFromString(""), Error);
}

// A lot frame with boxes, round and polygonal obstacles (prisms), paths, arrows and overlay
// text, as the frame recorder draws it.
Scene lotFrame(const Scenario& lot) {
  static const std::vector<Pose2> planned = {
      {0.1, 0.1, 1.2}, {0.3, 0.4, 0.6}, {0.8, 0.45, 0.0}, {1.2, 0.3, -0.8}, {1.5, 0.04, -1.5}};
  static const std::vector<Pose2> executed = {{0.1, 0.1, 1.2}, {0.31, 0.41, 0.6}};
  const ViewState view = rendertest::drivingView(planned, executed, {0.3, 0.4, 0.62},
                                                 {"backend test", 1.25, 0.0012, 0.004});
  const FrameDef frames;
  return buildScene(lot, view, frames.style);
}

Scenario lotWithPrisms() {
  Scenario lot = rendertest::testLot();
  lot.obstacles.push_back(
      Obstacle::makeCircle("bollard", ObstacleKind::kBollard, Circle{{0.9, 0.9}, 0.04}, 0.12));
  lot.obstacles.push_back(Obstacle::makePolygon(
      "kerb", ObstacleKind::kCurb, {{0.2, 0.9}, {0.4, 0.85}, {0.45, 1.05}, {0.25, 1.1}}, 0.02));
  return lot;
}

struct View {
  std::string name;
  Scene scene;
  CameraDef camera;
  int width_px;
  int height_px;
  int msaa_samples;
};

std::vector<View> views() {
  const Scenario lot = lotWithPrisms();
  const FrameDef frames;
  std::vector<View> out;
  out.push_back({"top frame", lotFrame(lot), CameraDef{}, 640, 480, 1});
  out.push_back({"perspective frame", lotFrame(lot), frames.camera_3d, 640, 480, 1});
  out.push_back({"perspective frame, msaa", lotFrame(lot), frames.camera_3d, 320, 240, 4});
  const FigureDef figures;
  const SceneStyle style = figures.style.scaled(800.0 / 480.0);
  out.push_back({"lot map figure, msaa", buildLotMapFigure(lot, style), figureCamera("lot_map"),
                 1200, 800, 4});
  out.push_back({"C-space stack figure, msaa", buildCSpaceStackFigure(lot, 12, style),
                 figureCamera("cspace_stack"), 600, 400, 4});
  return out;
}

std::size_t distinctColours(const RgbImage& img) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < img.pixels.size(); i += 3) {
    colours.insert(static_cast<std::uint32_t>(img.pixels[i]) << 16 |
                   static_cast<std::uint32_t>(img.pixels[i + 1]) << 8 | img.pixels[i + 2]);
  }
  return colours.size();
}

// Both backends draw with llvmpipe, so the same scene gives the same bytes. The two renderers
// live side by side and take turns on one thread, as they may in one process.
TEST(OffscreenContextTest, EglAndOsMesaDrawIdenticalImages) {
  if (!contextBackendBuilt(ContextBackend::kOsMesa)) GTEST_SKIP() << "built without OSMesa";
  for (const View& v : views()) {
    SCOPED_TRACE(v.name);
    RenderDef def;
    def.width_px = v.width_px;
    def.height_px = v.height_px;
    def.msaa_samples = v.msaa_samples;
    def.context.backend = ContextBackend::kEgl;
    Renderer egl(def);
    def.context.backend = ContextBackend::kOsMesa;
    Renderer osmesa(def);
    ASSERT_EQ(egl.backend(), ContextBackend::kEgl);
    ASSERT_EQ(osmesa.backend(), ContextBackend::kOsMesa);
    ASSERT_EQ(egl.samples(), v.msaa_samples);
    ASSERT_EQ(osmesa.samples(), v.msaa_samples);
    RgbImage a;
    RgbImage b;
    RgbImage again;
    egl.render(v.scene, v.camera, a);
    osmesa.render(v.scene, v.camera, b);
    egl.render(v.scene, v.camera, again);  // after the other context was current
    ASSERT_EQ(a.width, v.width_px);
    EXPECT_GT(distinctColours(a), 20u);  // drawn, with text and anti-aliased edges
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
    EXPECT_EQ(differing, 0u) << "bytes differ between EGL and OSMesa";
    EXPECT_EQ(a.pixels, again.pixels);
  }
}

// A renderer may move between threads, one at a time (EGL refuses a context that is still
// current on another thread, so the renderer releases it after each image).
TEST(OffscreenContextTest, ARendererMovesBetweenThreads) {
  for (ContextBackend backend : {ContextBackend::kEgl, ContextBackend::kOsMesa}) {
    if (!contextBackendBuilt(backend)) continue;
    SCOPED_TRACE(toString(backend));
    RenderDef def;
    def.width_px = 160;
    def.height_px = 120;
    def.context.backend = backend;
    Renderer renderer(def);
    const View v = views().front();
    RgbImage here;
    RgbImage there;
    RgbImage back;
    renderer.render(v.scene, v.camera, here);
    std::thread other([&] { renderer.render(v.scene, v.camera, there); });
    other.join();
    renderer.render(v.scene, v.camera, back);
    EXPECT_EQ(here.pixels, there.pixels);
    EXPECT_EQ(here.pixels, back.pixels);
  }
}

// GL object names are per context: the next buffer name tells which context a call reached.
GLuint nextBufferName(const GlFunctions& gl) {
  GLuint name = 0;
  gl.GenBuffers(1, &name);
  return name;
}

// Making one backend's context current must not leave the other's believing it still is (both
// go through Mesa's one dispatch table), or its calls would reach the wrong context.
TEST(OffscreenContextTest, CallsReachTheirOwnContextAcrossBackends) {
  if (!contextBackendBuilt(ContextBackend::kOsMesa)) GTEST_SKIP() << "built without OSMesa";
  ContextDef def;
  def.backend = ContextBackend::kEgl;
  const auto egl = createOffscreenContext(def);
  for (int i = 0; i < 10; ++i) nextBufferName(egl->gl());
  def.backend = ContextBackend::kOsMesa;
  const auto osmesa = createOffscreenContext(def);
  EXPECT_TRUE(osmesa->isCurrent());
  EXPECT_FALSE(egl->isCurrent());
  const GLuint in_osmesa = nextBufferName(osmesa->gl());
  egl->makeCurrent();
  EXPECT_FALSE(osmesa->isCurrent());
  const GLuint in_egl = nextBufferName(egl->gl());
  EXPECT_EQ(in_egl, in_osmesa + 10);
}

using testing::mapped;

// What BackendsLoadTheirLibrariesOnFirstUse checks, in a process of its own; returns the
// first broken expectation, or empty.
std::string firstUseProblem() {
  if (mapped("libEGL.so") || mapped("libOSMesa") || mapped("libLLVM")) {
    return "a GL library is mapped at start-up";
  }
  // Building and tessellating scenes needs no GL.
  const Scenario lot = lotWithPrisms();
  SceneTessellator tessellator;
  FontCache fonts(readFontFile(findFontFile()));
  DrawList list;
  const Scene scene = lotFrame(lot);
  tessellator.tessellate(scene, makeCamera({}, scene, 640, 480), {}, fonts, list);
  if (list.triangleCount() == 0) return "nothing tessellated";
  if (mapped("libEGL.so") || mapped("libOSMesa")) return "tessellating loaded a GL library";
  ContextDef def;
  std::unique_ptr<OffscreenContext> osmesa;
  if (contextBackendBuilt(ContextBackend::kOsMesa)) {
    // OSMesa first, EGL after it: OSMesa must still release the EGL context it finds current.
    def.backend = ContextBackend::kOsMesa;
    osmesa = createOffscreenContext(def);
    if (!mapped("libOSMesa") || mapped("libEGL.so")) return "OSMesa loaded the wrong libraries";
  }
  def.backend = ContextBackend::kEgl;
  const auto egl = createOffscreenContext(def);
  if (!mapped("libEGL.so")) return "EGL did not load libEGL";
  if (!osmesa) return mapped("libOSMesa") ? "EGL loaded libOSMesa" : "";
  for (int i = 0; i < 10; ++i) nextBufferName(egl->gl());
  osmesa->makeCurrent();
  if (egl->isCurrent()) return "the EGL context stayed current under OSMesa";
  const GLuint in_osmesa = nextBufferName(osmesa->gl());
  egl->makeCurrent();
  if (nextBufferName(egl->gl()) != in_osmesa + 10) return "calls reached the wrong context";
  return "";
}

// The GL backends' libraries (libEGL; libOSMesa with LLVM) are loaded when a context of theirs
// is first made, not at start-up: a death test runs this in a fresh process.
TEST(OffscreenContextDeathTest, BackendsLoadTheirLibrariesOnFirstUse) {
  testing::expectNoProblemInAFreshProcess(firstUseProblem);
}

}  // namespace offscreen_context_test
}  // namespace parksim
