// A film's memory: the frames it holds follow FrameDef::frame_memory_bytes, and a recording's
// peak resident memory grows with the frame by the renderer's framebuffers and those frames
// only (docs/limits.md). Issue 39: an 8192x8192 film of both views peaked at 4.99 GB.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "RenderTestUtil.h"
#include "parksim/core/io/Error.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "tests/support/Sanitizers.h"

namespace parksim {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

// What the GL holds for one view of `pixels`, one sample each: the drawing framebuffer's colour
// (RGBA8) and depth (24 bits, stored in 4 bytes by Mesa), and the same again for the top
// view's kept backdrop (Renderer::renderInto with a backdrop).
std::size_t framebufferBytes(std::size_t pixels) { return pixels * (4 + 4) * 2; }

TEST(FilmBuffersTest, FramesInFlightAreFewerAsFramesGrow) {
  FrameDef def;  // 640x480, top view: everything fits, as before the budget
  FilmBuffers b = filmBuffers(def);
  EXPECT_EQ(b.frame_bytes, std::size_t{640} * 480 * 4);
  EXPECT_EQ(b.images, def.queue_depth + def.encode_threads);
  EXPECT_EQ(b.kept, 1);

  def.width_px = def.height_px = 4096;
  def.view = FrameView::kBoth;  // 128 MiB a frame: the kept one and 3 of the 4 in flight
  b = filmBuffers(def);
  EXPECT_EQ(b.frame_bytes, 128 * kMiB);
  EXPECT_EQ(b.kept, 1);
  EXPECT_EQ(b.images, 3);
  EXPECT_LE(b.bytes(), def.frame_memory_bytes);

  def.width_px = def.height_px = 8192;  // 512 MiB: one frame in flight, none kept
  b = filmBuffers(def);
  EXPECT_EQ(b.kept, 0);
  EXPECT_EQ(b.images, 1);
  EXPECT_EQ(b.bytes(), 512 * kMiB);

  def.view = FrameView::kTop;  // 256 MiB: the kept one and one in flight
  b = filmBuffers(def);
  EXPECT_EQ(b.kept, 1);
  EXPECT_EQ(b.images, 1);

  def.frame_memory_bytes = 0;  // one frame in flight always; nothing kept
  b = filmBuffers(def);
  EXPECT_EQ(b.kept, 0);
  EXPECT_EQ(b.images, 1);

  def.frame_memory_bytes = std::size_t{1} << 40;  // no more than the queue asks for
  def.encode_threads = 2;
  b = filmBuffers(def);
  EXPECT_EQ(b.kept, 2);
  EXPECT_EQ(b.images, def.queue_depth + 2);

  def.png_compression = PngCompression::kStored;  // keeps no last image
  EXPECT_EQ(filmBuffers(def).kept, 0);
}

TEST(FilmBuffersTest, TheLargestFilmFitsInTwoGigabytes) {
  // The largest film the options allow, as `run --frames --size 8192x8192 --view both` makes
  // it, and the largest top view: framebuffers and frames within 2 GB less 300 MB for the rest
  // of the process (parksim run measured 110 to 160 MB besides them).
  for (FrameView view : {FrameView::kBoth, FrameView::kTop}) {
    FrameDef def;
    def.width_px = def.height_px = 8192;
    def.view = view;
    const std::size_t total = framebufferBytes(std::size_t{8192} * 8192) + filmBuffers(def).bytes();
    EXPECT_LE(total, std::size_t{2'000'000'000} - 300'000'000) << toString(view);
  }
}

// Each combination the options allow at the largest size is filmed within the bound, or refused
// before any work with one line naming the options, the computed bytes and the bound.
TEST(FilmBuffersTest, EveryCombinationFitsTheBoundOrIsRefused) {
  const std::size_t pixels = std::size_t{8192} * 8192;  // one view
  const std::size_t frame = 2 * pixels * 4;             // both views, RGBA
  FrameDef def;
  def.width_px = def.height_px = 8192;
  def.view = FrameView::kBoth;
  // The default: framebuffers (16 bytes a pixel), one frame in flight and the queued samples.
  EXPECT_EQ(filmPeakBytes(def), 16 * pixels + frame + 32 * kMiB);
  EXPECT_LE(filmPeakBytes(def), kFilmMemoryBoundBytes);
  EXPECT_NO_THROW(checkFilmMemory(def));
  def.png_compression = PngCompression::kFast;
  EXPECT_NO_THROW(checkFilmMemory(def));

  // Stored: the encoder's whole file besides (3 bytes a pixel), over the bound.
  def.png_compression = PngCompression::kStored;
  EXPECT_EQ(filmPeakBytes(def), 16 * pixels + frame + frame / 4 * 3 + 32 * kMiB);
  try {
    checkFilmMemory(def);
    ADD_FAILURE() << "stored at 8192x8192, both views, was not refused";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find("size 8192x8192, view both, png_compression stored"), std::string::npos)
        << what;
    EXPECT_NE(what.find(std::to_string(filmPeakBytes(def)) + " bytes"), std::string::npos) << what;
    EXPECT_NE(what.find(std::to_string(kFilmMemoryBoundBytes)), std::string::npos) << what;
  }
  // Small: an RGB copy, stb's filtered image and its output.
  def.png_compression = PngCompression::kSmall;
  EXPECT_EQ(filmPeakBytes(def), 16 * pixels + frame + 3 * (frame / 4 * 3) + 32 * kMiB);
  EXPECT_THROW(checkFilmMemory(def), Error);
  // Four samples: 16 x 4 + 4 bytes a pixel of framebuffers.
  def.png_compression = PngCompression::kDefault;
  def.msaa_samples = 4;
  EXPECT_EQ(filmPeakBytes(def), 68 * pixels + frame + 32 * kMiB);
  EXPECT_THROW(checkFilmMemory(def), Error);
  // A budget larger than the bound.
  def.msaa_samples = 1;
  def.width_px = def.height_px = 4096;
  def.frame_memory_bytes = std::size_t{4} << 30;
  def.queue_depth = 40;
  EXPECT_THROW(checkFilmMemory(def), Error);

  // Where each fits: 640x480, and the largest stored and small top views that do.
  for (PngCompression c : {PngCompression::kDefault, PngCompression::kFast, PngCompression::kStored,
                           PngCompression::kSmall}) {
    FrameDef fits;
    fits.view = FrameView::kBoth;
    fits.png_compression = c;
    fits.msaa_samples = 4;
    EXPECT_NO_THROW(checkFilmMemory(fits)) << toString(c);
  }
}

// A recording refused for its memory makes nothing, not even its directory.
TEST(FilmBuffersTest, ARefusedRecordingWritesNothing) {
  FrameDef def;
  def.width_px = def.height_px = 8192;
  def.view = FrameView::kBoth;
  def.png_compression = PngCompression::kStored;
  def.out_dir = rendertest::outputDir("FilmMemoryTest_refused");
  std::filesystem::remove_all(def.out_dir);
  EXPECT_THROW({ FrameRecorder rec(rendertest::testLot(), def); }, Error);
  EXPECT_FALSE(std::filesystem::exists(def.out_dir + "/frames"));
}

long maxResidentKiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// Films three frames of the test lot with `def`; the robot moves between them.
void film(const FrameDef& def) {
  const Scenario lot = rendertest::testLot();
  FrameRecorder rec(lot, def);
  rec.setPlan(rendertest::sampleDrive(lot.robot, lot.start));
  for (int k = 0; k < 3; ++k) {
    FrameInput in;
    in.t_s = k / def.fps;
    in.pose = {lot.start.x + 0.05 * k, lot.start.y + 0.02 * k, lot.start.theta};
    in.reference = in.pose;
    rec.addFrame(in);
  }
  rec.finish();
}

// In a fresh process (a death test): films a few frames small, so that the GL libraries, fonts
// and threads are in, then `def`'s film, and exits 0 when the peak resident memory grew by at
// most the framebuffers of its view, `frames` frames of its size and `slack`.
void expectPeakWithin(const FrameDef& def, double frames, std::size_t slack) {
  if (testing::kSanitized) GTEST_SKIP() << "the sanitizers' shadow memory is resident too";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::size_t view_pixels = static_cast<std::size_t>(def.width_px) * def.height_px;
  const std::size_t views = def.view == FrameView::kBoth ? 2 : 1;
  const std::size_t frame_bytes = views * view_pixels * 4;
  const double bound =
      framebufferBytes(view_pixels) + frames * static_cast<double>(frame_bytes) + slack;
  EXPECT_EXIT(
      {
        FrameDef small = def;
        small.width_px = 64;
        small.height_px = 48;
        small.out_dir = def.out_dir + "_small";
        film(small);
        const long before = maxResidentKiB();
        film(def);
        const double grew = 1024.0 * static_cast<double>(maxResidentKiB() - before);
        std::fprintf(stderr, "peak grew by %.1f MiB, bound %.1f MiB\n", grew / kMiB, bound / kMiB);
        std::exit(grew <= bound ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "peak grew");
}

FrameDef bothViews(const std::string& name, int side_px) {
  FrameDef def;
  def.fps = 2.0;
  def.width_px = def.height_px = side_px;
  def.view = FrameView::kBoth;
  def.out_dir = rendertest::outputDir(name);
  return def;
}

// 4096x4096, both views (docs/limits.md measures it): 128 MiB a frame, of which the default
// budget (512 MiB) lets the encoder keep 1 and the film hold 3 in flight (of queue_depth 3 + 1
// encoder). Before issue 39 the film held 4 in flight, and the encoder a copy of the last frame
// as it came and in RGB (3/4 of a frame) and two outputs of the whole image's deflate bound (3/4
// of a frame each): 9.25 frames with the framebuffers' 2 (1.33 GB measured), where 6 are
// allowed now.
TEST(FilmMemoryDeathTest, AFilmHoldsItsFramebuffersAndBudgetedFramesOnly) {
  expectPeakWithin(bothViews("FilmMemoryTest_default", 4096), 4.0, 48 * kMiB);
}

// With no budget: one frame in flight, none kept.
TEST(FilmMemoryDeathTest, WithNoBudgetAFilmHoldsOneFrame) {
  FrameDef def = bothViews("FilmMemoryTest_none", 2048);
  def.frame_memory_bytes = 0;
  expectPeakWithin(def, 1.0, 24 * kMiB);
}

}  // namespace
}  // namespace parksim
