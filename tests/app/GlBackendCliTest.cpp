// parksim run and render choose their OpenGL backend: --gl-backend, else PARKSIM_GL_BACKEND,
// else EGL then OSMesa; frames and figures are the same bytes through either backend.

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;
using testing::runParksim;
using testing::slurp;

// Sets (or unsets) an environment variable for the commands one test runs.
class EnvVar {
 public:
  EnvVar(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    set(value);
  }
  ~EnvVar() { set(old_ ? old_->c_str() : nullptr); }
  EnvVar(const EnvVar&) = delete;
  EnvVar& operator=(const EnvVar&) = delete;

  void set(const char* value) const {
    if (value != nullptr) {
      ::setenv(name_.c_str(), value, 1);
    } else {
      ::unsetenv(name_.c_str());
    }
  }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

class GlBackendCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = parksim::testing::testOutputDir(
        "gl_backend_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string world(const std::string& name) {
    return parksim::testing::sourceDir() + "/worlds/" + name;
  }
  // A short film: 2 frames per simulated second, small frames.
  CliRun film(const std::string& name, const std::string& options) {
    return runParksim("run " + world("head_in.yaml") + " --frames --fps 2 --size 160x120 " +
                      options + " --out " + (dir_ / name).string());
  }
  std::string glOf(const std::string& name) {
    const auto m = nlohmann::json::parse(slurp(dir_ / name / "metrics.json"));
    return m.value("provenance.gl", "");
  }
  // Every frame and figure of film `a` has the bytes of film `b`'s file of that name.
  void expectSameFrameAndFigureBytes(const std::string& a, const std::string& b) {
    int files = 0;
    for (const char* sub : {"frames", "figures"}) {
      for (const auto& e : fs::directory_iterator(dir_ / a / sub)) {
        const fs::path other = dir_ / b / sub / e.path().filename();
        EXPECT_EQ(slurp(e.path()), slurp(other)) << other;
        ++files;
      }
    }
    EXPECT_GT(files, 20);
  }
  fs::path dir_;
};

TEST_F(GlBackendCli, UnknownBackendIsRefusedWithOneLine) {
  const EnvVar env("PARKSIM_GL_BACKEND", nullptr);
  const fs::path out = dir_ / "never";
  for (const char* cmd : {"render ", "run "}) {
    const CliRun r = runParksim(std::string(cmd) + world("head_in.yaml") +
                                " --frames --gl-backend vulkan --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_EQ(r.out.substr(0, r.out.find('\n')),
              "parksim: error: --gl-backend: vulkan not in {auto,egl,osmesa}");
  }
  env.set("vulkan");
  const CliRun r = runParksim("render " + world("head_in.yaml") + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(r.out,
            "parksim: error: PARKSIM_GL_BACKEND: unknown OpenGL backend 'vulkan' (auto, egl or "
            "osmesa)\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(GlBackendCli, OptionBeatsEnvironmentAndBothBackendsFilmTheSameBytes) {
  // Without either: EGL on Mesa's software device.
  const EnvVar env("PARKSIM_GL_BACKEND", nullptr);
  ASSERT_EQ(film("auto", "").exit_code, 0);
  EXPECT_EQ(glOf("auto").rfind("EGL (device: software): ", 0), 0u) << glOf("auto");
  // The environment chooses when the option does not, and the option wins over it.
  env.set("osmesa");
  const CliRun osmesa = film("osmesa", "");
  if (osmesa.exit_code == 2 && osmesa.out.find("built without OSMesa") != std::string::npos) {
    GTEST_SKIP() << "built without OSMesa";
  }
  ASSERT_EQ(osmesa.exit_code, 0) << osmesa.out;
  EXPECT_EQ(glOf("osmesa").rfind("OSMesa: ", 0), 0u) << glOf("osmesa");
  ASSERT_EQ(film("option", "--gl-backend egl").exit_code, 0);
  EXPECT_EQ(glOf("option").rfind("EGL ", 0), 0u) << glOf("option");

  expectSameFrameAndFigureBytes("osmesa", "auto");
}

// The program has llvmpipe rasterize in its drawing thread unless LP_NUM_THREADS says otherwise
// (cli::startProgram); frames and figures are the same bytes with rasterizer threads.
TEST_F(GlBackendCli, LlvmpipeThreadsDoNotChangeTheBytes) {
  const EnvVar env("PARKSIM_GL_BACKEND", nullptr);
  const EnvVar threads("LP_NUM_THREADS", nullptr);
  ASSERT_EQ(film("default", "--view both").exit_code, 0);
  threads.set("3");
  ASSERT_EQ(film("threads", "--view both").exit_code, 0);
  expectSameFrameAndFigureBytes("default", "threads");
}

// glvnd's libEGL without a vendor library: EGL cannot make a context.
TEST_F(GlBackendCli, WithoutEglAutoFallsBackToOsMesaAndEglAloneExitsWithThree) {
  const EnvVar env("PARKSIM_GL_BACKEND", nullptr);
  const EnvVar no_vendor("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/parksim_egl.json");
  const fs::path never = dir_ / "never";
  const CliRun egl =
      runParksim("render " + world("head_in.yaml") + " --gl-backend egl --out " + never.string());
  if (egl.exit_code == 0) GTEST_SKIP() << "libEGL is not glvnd's: the variable does not remove EGL";
  EXPECT_EQ(egl.exit_code, 3) << egl.out;  // the machine's fault, not the input's
  EXPECT_EQ(egl.out.rfind("parksim: error: EGL: ", 0), 0u) << egl.out;
  EXPECT_EQ(egl.out.find('\n'), egl.out.size() - 1) << egl.out;  // one line
  EXPECT_FALSE(fs::exists(never));
  // A film finds it out on its drawing thread, while the simulation goes on: the same error,
  // and nothing written.
  const CliRun film_egl = runParksim("run " + world("head_in.yaml") +
                                     " --frames --gl-backend egl --out " + never.string());
  EXPECT_EQ(film_egl.exit_code, 3) << film_egl.out;
  EXPECT_EQ(film_egl.out, egl.out);
  EXPECT_FALSE(fs::exists(never));

  const CliRun fallback = film("auto", "");
  if (fallback.out.find("built without OSMesa") != std::string::npos) {
    EXPECT_EQ(fallback.exit_code, 3) << fallback.out;
    EXPECT_NE(fallback.out.find("no OpenGL context: EGL: "), std::string::npos) << fallback.out;
    return;
  }
  ASSERT_EQ(fallback.exit_code, 0) << fallback.out;
  EXPECT_EQ(glOf("auto").rfind("OSMesa: ", 0), 0u) << glOf("auto");
}

}  // namespace
}  // namespace parksim
