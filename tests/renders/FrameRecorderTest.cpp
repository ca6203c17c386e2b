#include "parksim/renders/film/FrameRecorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

#include "RenderTestUtil.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/system/Process.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/scene/SceneBuilder.h"

namespace parksim {
namespace {

using rendertest::outputDir;
using rendertest::testLot;

std::vector<char> fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Feeds a planned drive at 240 Hz, the executed pose lagging the plan a little.
int record(FrameRecorder& rec, const Scenario& s, const Trajectory& plan) {
  const std::vector<Pose2> path = samplePath(plan, s.robot, 0.0005, 0.01);
  int frames = 0;
  const double duration = plan.duration();
  const int steps = static_cast<int>(duration * 240.0);
  for (int k = 0; k <= steps; ++k) {
    FrameInput in;
    in.t_s = k / 240.0;
    const std::size_t i = path.size() * static_cast<std::size_t>(k) / (steps + 1);
    in.reference = path[i];
    in.pose = path[i > 3 ? i - 3 : 0];
    in.position_error_m = positionDistance(*in.reference, in.pose);
    in.heading_error_rad = angleDiff(in.pose.theta, in.reference->theta);
    frames += rec.addFrame(in);
  }
  return frames;
}

// A recorder's definition: frames into outputDir(name), at fps, of width x height pixels.
FrameDef filmDef(const std::string& name, double fps, int width_px, int height_px) {
  FrameDef def;
  def.fps = fps;
  def.width_px = width_px;
  def.height_px = height_px;
  def.out_dir = outputDir(name);
  return def;
}

class FrameRecorderTest : public ::testing::Test {
 protected:
  Scenario lot_ = testLot();
  Trajectory plan_ = rendertest::sampleDrive(lot_.robot, lot_.start);  // 4 s
};

TEST_F(FrameRecorderTest, WritesValidChangingFramesAtTheFrameRate) {
  FrameDef def = filmDef("FrameRecorderTest_rate", 10.0, 320, 240);
  FrameRecorder rec(lot_, def);
  rec.setPlan(plan_);
  const int rendered = record(rec, lot_, plan_);
  EXPECT_EQ(rendered, 41);  // t = 0, 0.1, ..., 4.0
  const RecordingResult result = rec.finish();
  EXPECT_EQ(result.frames, 41);
  EXPECT_EQ(result.video.status, VideoStatus::kNotRequested);
  EXPECT_NE(result.message.find("41 frames"), std::string::npos) << result.message;
  RgbImage previous;
  int changed = 0;
  for (int i = 0; i < result.frames; ++i) {
    const RgbImage img = readPng(rec.framePath(i));
    ASSERT_EQ(img.width, 320);
    ASSERT_EQ(img.height, 240);
    if (i > 0) changed += img != previous;
    previous = img;
  }
  EXPECT_EQ(changed, 40);  // the robot moves and the clock runs in every frame
  EXPECT_FALSE(std::filesystem::exists(rec.framePath(41)));
}

// Progress counts frames written, not samples handed over: the drawing thread may be far
// behind. finish() reports the count while it waits, ending with every frame.
TEST_F(FrameRecorderTest, FinishReportsTheFramesWritten) {
  FrameDef def = filmDef("FrameRecorderTest_progress", 10.0, 320, 240);
  FrameRecorder rec(lot_, def);
  rec.setPlan(plan_);
  EXPECT_EQ(rec.framesWritten(), 0);
  const int due = record(rec, lot_, plan_);
  EXPECT_LE(rec.framesWritten(), due);
  std::vector<long> reported;
  const RecordingResult result = rec.finish([&](long written) { reported.push_back(written); });
  ASSERT_FALSE(reported.empty());
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  EXPECT_EQ(reported.back(), result.frames);
  EXPECT_EQ(rec.framesWritten(), result.frames);
  EXPECT_EQ(result.frames, 41);
}

TEST_F(FrameRecorderTest, FramesShowTheRobotWhereTheSampleSaysItIs) {
  FrameDef def;
  def.out_dir = outputDir("FrameRecorderTest_robot");
  FrameRecorder rec(lot_, def);
  FrameInput in;
  in.pose = {1.0, 0.35, 0.4};
  EXPECT_EQ(rec.addFrame(in), 1);
  rec.finish();
  const RgbImage img = readPng(rec.framePath(0));
  ViewState view;
  view.robot = in.pose;
  const SceneStyle style = def.style.scaled(styleScaleFor(def.height_px));
  const Camera cam = makeCamera({}, buildScene(lot_, view, style), def.width_px, def.height_px);
  const OrientedBox body = footprintAt(lot_.robot, in.pose);
  const auto p = cam.project({body.center.x(), body.center.y(), lot_.robot.height_m});
  ASSERT_TRUE(p);
  EXPECT_EQ(img.at(static_cast<int>(p->x()), static_cast<int>(p->y())), def.style.robot);
}

// The top view keeps the lot's pixels from frame to frame; a touched obstacle must still turn
// red, and a pushed one move, in the very frame that says so.
TEST_F(FrameRecorderTest, FramesShowObstaclesTouchedAndPushed) {
  FrameDef def;
  def.out_dir = outputDir("FrameRecorderTest_pushed");
  FrameRecorder rec(lot_, def);
  const Obstacle& first = lot_.obstacles.front();
  std::vector<Pose2> poses;
  for (const Obstacle& o : lot_.obstacles)
    poses.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
  FrameInput in;
  in.pose = {1.0, 0.35, 0.4};
  in.obstacle_poses = poses;
  in.t_s = 0.0;
  rec.addFrame(in);  // as in the scenario
  in.t_s = 1.0 / def.fps;
  in.contacts = {0};
  rec.addFrame(in);  // touched
  in.t_s = 2.0 / def.fps;
  in.contacts = {};
  in.obstacle_poses.front().x += 0.06;
  rec.addFrame(in);  // pushed
  EXPECT_EQ(rec.finish().lot_drawings, 3);

  const SceneStyle style = def.style.scaled(styleScaleFor(def.height_px));
  ViewState view;
  view.robot = in.pose;
  const Camera cam = makeCamera({}, buildScene(lot_, view, style), def.width_px, def.height_px);
  auto colourAt = [&](int frame, double x, double y) {
    const auto p = cam.project({x, y, first.height_m});
    if (!p) return Rgba8{};  // not in the image: no obstacle colour, the check fails
    return readPng(rec.framePath(frame)).at(static_cast<int>(p->x()), static_cast<int>(p->y()));
  };
  const double x = first.box.center.x();
  const double y = first.box.center.y();
  const double edge = x + first.box.half_extents.x();  // the obstacle's right side (no yaw)
  ASSERT_EQ(first.box.yaw, 0.0);
  EXPECT_EQ(colourAt(0, x, y), style.colorFor(first.kind));
  EXPECT_EQ(colourAt(1, x, y), style.contact);
  EXPECT_EQ(colourAt(2, edge + 0.03, y), style.colorFor(first.kind));
  EXPECT_NE(colourAt(0, edge + 0.03, y), style.colorFor(first.kind));
}

// Resting bodies creep by nanometres in the simulation: frames show them where they were until
// they moved more than 10 um, so the lot stays the same picture (and stays kept).
TEST_F(FrameRecorderTest, ObstaclesCreepingInvisiblyAreShownWhereTheyRest) {
  std::vector<Pose2> rest;
  for (const Obstacle& o : lot_.obstacles) {
    rest.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
  }
  auto film = [&](const std::string& name, double creep_m) {
    FrameDef def;
    def.out_dir = outputDir(name);
    FrameRecorder rec(lot_, def);
    FrameInput in;
    in.pose = {1.0, 0.35, 0.4};
    in.obstacle_poses = rest;
    for (int k = 0; k < 5; ++k) {
      in.t_s = k / def.fps;
      for (Pose2& p : in.obstacle_poses) p.x += creep_m;
      rec.addFrame(in);
    }
    const RecordingResult result = rec.finish();
    std::vector<std::vector<char>> frames;
    for (int k = 0; k < 5; ++k) frames.push_back(fileBytes(rec.framePath(k)));
    return std::pair{frames, result.lot_drawings};
  };
  const auto [still, still_drawings] = film("FrameRecorderTest_still", 0.0);
  const auto [creeping, creeping_drawings] = film("FrameRecorderTest_creeping", 1.5e-6);
  const auto [moving, moving_drawings] = film("FrameRecorderTest_moving", 2e-3);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(creeping[k], still[k]) << "frame " << k;
  EXPECT_NE(moving[4], still[4]);
  EXPECT_EQ(still_drawings, 1);
  EXPECT_EQ(creeping_drawings, 1);  // 7.5 um in all
  EXPECT_EQ(moving_drawings, 5);
}

// One encoder is told which rows of a top view changed (Renderer::renderChanges); two take
// whole images; one with no memory to spare (frame_memory_bytes 0: one frame in flight, no last
// frame kept) takes whole images and compresses every band: the bytes are the same.
TEST_F(FrameRecorderTest, OutputDoesNotDependOnThreads) {
  for (FrameView view : {FrameView::kTop, FrameView::kBoth}) {
    for (PngCompression png :
         {PngCompression::kDefault, PngCompression::kFast, PngCompression::kStored}) {
      const std::string name = std::string(view == FrameView::kTop ? "top" : "both") + "_";
      std::vector<std::string> dirs;
      for (const auto& [threads, memory] :
           {std::pair{1, FrameDef{}.frame_memory_bytes},
            std::pair{2, FrameDef{}.frame_memory_bytes}, std::pair{1, std::size_t{0}}}) {
        FrameDef def;
        def.fps = 5.0;
        def.width_px = 200;
        def.height_px = 150;
        def.view = view;
        def.encode_threads = threads;
        def.frame_memory_bytes = memory;
        def.png_compression = png;
        def.out_dir = outputDir("FrameRecorderTest_threads" + name + std::to_string(threads) +
                                (memory == 0 ? "_nomemory_" : "_") + toString(png));
        FrameRecorder rec(lot_, def);
        rec.setPlan(plan_);
        record(rec, lot_, plan_);
        EXPECT_EQ(rec.finish().frames, 21);
        dirs.push_back(def.out_dir + "/frames");
      }
      for (int i = 0; i <= 20; ++i) {
        char file[16];
        std::snprintf(file, sizeof file, "/%06d.png", i);
        const std::vector<char> a = fileBytes(dirs[0] + file);
        ASSERT_FALSE(a.empty());
        EXPECT_EQ(a, fileBytes(dirs[1] + file)) << name << toString(png) << file;
        EXPECT_EQ(a, fileBytes(dirs[2] + file)) << name << toString(png) << file << ", no memory";
      }
      const RgbImage first = readPng(dirs[0] + "/000000.png");
      EXPECT_EQ(first.width, view == FrameView::kTop ? 200 : 400);  // views side by side
      EXPECT_EQ(first.height, 150);
      if (png != PngCompression::kDefault) {
        // The same pixels as the default's (recorded first), in other bytes.
        const std::string default_frames =
            dirs[0].substr(0, dirs[0].rfind('_')) + "_default/frames/000000.png";
        EXPECT_EQ(first, readPng(default_frames));
      }
    }
  }
}

TEST_F(FrameRecorderTest, SparseSamplesRepeatFramesAndTheLastSampleEndsTheFilm) {
  FrameDef def = filmDef("FrameRecorderTest_sparse", 10.0, 160, 120);
  FrameRecorder rec(lot_, def);
  FrameInput in;
  in.t_s = 1.0;
  EXPECT_EQ(rec.addFrame(in), 1);  // the first sample opens the film
  in.t_s = 1.35;
  EXPECT_EQ(rec.addFrame(in), 3);  // 1.1, 1.2, 1.3
  in.t_s = 1.37;
  EXPECT_EQ(rec.addFrame(in), 0);
  in.t_s = 1.2;
  EXPECT_THROW(rec.addFrame(in), Error);
  EXPECT_EQ(rec.finish().frames, 5);  // 1.37 gets a frame of its own
  EXPECT_THROW(rec.addFrame(in), Error);
}

TEST_F(FrameRecorderTest, MissingFfmpegIsReportedNotThrown) {
  const std::string empty_bin = outputDir("FrameRecorderTest_empty_bin");
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path != nullptr ? old_path : "";
  setenv("PATH", empty_bin.c_str(), 1);
  FrameDef def = filmDef("FrameRecorderTest_noffmpeg", 10.0, 160, 120);
  def.video = true;
  def.gif = true;
  RecordingResult result;
  {
    FrameRecorder rec(lot_, def);
    record(rec, lot_, plan_);
    result = rec.finish();
  }
  setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(result.frames, 41);
  EXPECT_EQ(result.video.status, VideoStatus::kFfmpegMissing);
  EXPECT_EQ(result.gif.status, VideoStatus::kFfmpegMissing);
  EXPECT_NE(result.video.message.find("ffmpeg"), std::string::npos) << result.video.message;
  EXPECT_NE(result.message.find("not on PATH"), std::string::npos) << result.message;
  EXPECT_FALSE(std::filesystem::exists(def.out_dir + "/episode.mp4"));
  EXPECT_TRUE(std::filesystem::exists(def.out_dir + "/frames/000040.png"));
}

TEST_F(FrameRecorderTest, MakesAVideoWhenFfmpegIsThere) {
  FrameDef def;
  if (findExecutable(def.ffmpeg).empty()) GTEST_SKIP() << "ffmpeg is not installed";
  def.fps = 10.0;
  def.width_px = 161;  // odd: the encoder pads to even sizes
  def.height_px = 121;
  def.video = true;
  def.gif = true;
  def.out_dir = outputDir("FrameRecorderTest_video");
  FrameRecorder rec(lot_, def);
  record(rec, lot_, plan_);
  const RecordingResult result = rec.finish();
  EXPECT_EQ(result.video.status, VideoStatus::kWritten) << result.video.message;
  EXPECT_EQ(result.gif.status, VideoStatus::kWritten) << result.gif.message;
  EXPECT_GT(std::filesystem::file_size(def.out_dir + "/episode.mp4"), 1000u);
  EXPECT_GT(std::filesystem::file_size(def.out_dir + "/episode.gif"), 1000u);
}

TEST_F(FrameRecorderTest, StaleFramesOfAnEarlierRecordingAreRemoved) {
  FrameDef def;
  def.width_px = 64;
  def.height_px = 48;
  def.out_dir = outputDir("FrameRecorderTest_stale");
  std::filesystem::create_directories(def.out_dir + "/frames");
  std::ofstream(def.out_dir + "/frames/000000.png") << "old";
  std::ofstream(def.out_dir + "/frames/000007.png") << "old";
  std::ofstream(def.out_dir + "/frames/notes.txt") << "kept";
  FrameRecorder rec(lot_, def);
  rec.addFrame({});
  EXPECT_EQ(rec.finish().frames, 1);
  EXPECT_FALSE(std::filesystem::exists(def.out_dir + "/frames/000007.png"));
  EXPECT_TRUE(std::filesystem::exists(def.out_dir + "/frames/notes.txt"));
  EXPECT_EQ(readPng(def.out_dir + "/frames/000000.png").width, 64);  // rewritten, not stale
}

// A caller far ahead of the drawing thread (thousands of samples while the GL context is still
// being made) waits for room and loses nothing: every frame is there, in order, and drawn from
// its own sample.
TEST_F(FrameRecorderTest, ACallerFarAheadOfTheDrawingWaitsAndLosesNothing) {
  FrameDef def = filmDef("FrameRecorderTest_ahead", 100.0, 32, 24);
  def.png_compression = PngCompression::kStored;
  FrameRecorder rec(lot_, def);
  const int samples = 5000;  // more than the drawing thread takes ahead (2048)
  for (int k = 0; k < samples; ++k) {
    FrameInput in;
    in.t_s = k / 100.0;
    in.pose = {0.2 + 1.4 * k / samples, 0.4, 0.0};
    ASSERT_EQ(rec.addFrame(in), 1) << k;
  }
  EXPECT_EQ(rec.finish().frames, samples);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(def.out_dir + "/frames")) {
    files += e.path().extension() == ".png";
  }
  EXPECT_EQ(files, samples);
  // The robot crosses the lot left to right, and each frame is its own sample's: what a fresh
  // recorder draws from that sample alone (at this size the driven path and the overlay's
  // text are below a pixel).
  for (int k : {1000, 2500, samples - 1}) {
    FrameDef one = def;
    one.out_dir = outputDir("FrameRecorderTest_ahead_" + std::to_string(k));
    FrameRecorder fresh(lot_, one);
    FrameInput in;
    in.t_s = k / 100.0;
    in.pose = {0.2 + 1.4 * k / samples, 0.4, 0.0};
    fresh.addFrame(in);
    fresh.finish();
    EXPECT_EQ(readPng(rec.framePath(k)), readPng(fresh.framePath(0))) << k;
    EXPECT_NE(readPng(rec.framePath(k)), readPng(rec.framePath(0))) << k;
  }
}

// The GL context is made on the drawing thread: when none can be made, the caller hears it from
// its next call, even one waiting for room in the queue, with the renderer's own error; and the
// recorder ends without hanging.
TEST_F(FrameRecorderTest, NoGlContextIsReportedByTheNextCall) {
  FrameDef def;
  def.out_dir = outputDir("FrameRecorderTest_no_gl");
  def.context.gl_major = 99;  // no backend makes an OpenGL 99 context
  {
    FrameRecorder rec(lot_, def);
    EXPECT_THROW(rec.glDescription(), Error);
    EXPECT_THROW(rec.setPlan(plan_), Error);
    EXPECT_THROW(rec.finish(), Error);
  }
  FrameRecorder rec(lot_, def);
  int k = 0;
  try {
    for (; k < 10'000; ++k) {  // more than the queue holds: a call waits, then hears it
      FrameInput in;
      in.t_s = k / 30.0;
      in.pose = {0.3, 0.3, 0.0};
      rec.addFrame(in);
    }
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("99"), std::string::npos) << e.what();
  }
  EXPECT_LT(k, 10'000);
  EXPECT_THROW(rec.finish(), Error);
}

// A sample that would pass max_frames is refused and changes nothing: the frames before it are
// the film, whole, with no gap.
TEST_F(FrameRecorderTest, TheFrameLimitLeavesTheRecorderAsItWas) {
  FrameDef def = filmDef("FrameRecorderTest_limit", 10.0, 32, 24);
  def.max_frames = 5;
  FrameRecorder rec(lot_, def);
  FrameInput in;
  for (int k = 0; k < 5; ++k) {
    in.t_s = k / 10.0;
    in.pose = {0.3 + 0.1 * k, 0.4, 0.0};
    ASSERT_EQ(rec.addFrame(in), 1);
  }
  in.t_s = 0.72;  // frames 5, 6 and 7 due
  try {
    rec.addFrame(in);
    FAIL() << "past the limit";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("more than the limit of 5 frames"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(rec.frames(), 5);
  EXPECT_EQ(rec.finish().frames, 5);
  for (int k = 0; k < 5; ++k) EXPECT_TRUE(std::filesystem::exists(rec.framePath(k))) << k;
  EXPECT_FALSE(std::filesystem::exists(rec.framePath(5)));
}

TEST_F(FrameRecorderTest, BadDefinitionsThrow) {
  FrameDef def;
  def.out_dir = outputDir("FrameRecorderTest_bad");
  def.fps = 0.0;
  EXPECT_THROW(FrameRecorder(lot_, def), Error);
  def.fps = 30.0;
  def.width_px = 0;
  EXPECT_THROW(FrameRecorder(lot_, def), Error);
  EXPECT_EQ(frameViewFromString("both"), FrameView::kBoth);
  EXPECT_THROW(frameViewFromString("side"), Error);
}

}  // namespace
}  // namespace parksim

namespace parksim {
namespace {

TEST(ImageSizeTest, ParsesWidthByHeight) {
  const ImageSize s = parseImageSize("1280x720");
  EXPECT_EQ(s.width_px, 1280);
  EXPECT_EQ(s.height_px, 720);
  EXPECT_EQ(parseImageSize("64X48").height_px, 48);
  for (const char* bad : {"", "640", "640x", "x480", "640x480x", "8x8", "640*480", "99999x2"}) {
    EXPECT_THROW(parseImageSize(bad), Error) << bad;
  }
}

}  // namespace
}  // namespace parksim
