#include "parksim/renders/film/FrameRecorder.h"

#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <regex>
#include <thread>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/system/Process.h"
#include "parksim/renders/film/EncodeQueue.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/scene/SceneBuilder.h"

namespace parksim {

const char* toString(FrameView view) {
  switch (view) {
    case FrameView::kTop: return "top";
    case FrameView::k3d: return "3d";
    case FrameView::kBoth: return "both";
  }
  return "?";
}

FrameView frameViewFromString(const std::string& name) {
  if (name == "top") return FrameView::kTop;
  if (name == "3d") return FrameView::k3d;
  if (name == "both") return FrameView::kBoth;
  throw Error("view must be top, 3d or both, got '" + name + "'");
}

ImageSize parseImageSize(const std::string& text) {
  // from_chars, not sscanf("%d"): 4294967936x480 must be refused, not wrapped to 640x480.
  auto side = [](std::string_view s, int& value) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return ec == std::errc() && end == s.data() + s.size() && value >= 16 && value <= 8192;
  };
  const std::size_t x = text.find_first_of("xX");
  ImageSize size;
  const std::string_view all(text);
  if (x == std::string::npos || !side(all.substr(0, x), size.width_px) ||
      !side(all.substr(x + 1), size.height_px)) {
    throw Error("size must be WxH with each side from 16 to 8192 pixels, e.g. 640x480, got '" +
                text.substr(0, 40) + (text.size() > 40 ? "...'" : "'"));
  }
  return size;
}

double checkFrameLimits(const FrameDef& def, double duration_s) {
  const double frames = std::floor(duration_s * def.fps) + 2.0;
  if (!(frames <= def.max_frames)) {
    throw Error("frames: " + formatGeneral(duration_s, 4) + " s of simulated time at " +
                formatGeneral(def.fps) + " fps are " + formatGeneral(frames, 4) +
                " frames, more than the limit of " + std::to_string(def.max_frames) +
                " (docs/limits.md)");
  }
  return frames;
}

namespace {

std::string framePathIn(const std::string& dir, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.png", index);
  return dir + "/" + name;
}

// Removes frame files (six digits .png) numbered `first` and above: an earlier, longer recording
// into the same directory must not add its tail to this one's video.
void removeFramesFrom(const std::string& dir, int first) {
  static const std::regex kFrameName("([0-9]{6})\\.png");
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && std::regex_match(name, m, kFrameName) &&
        std::stoi(m[1].str()) >= first) {
      std::filesystem::remove(entry.path(), ec);
    }
  }
}

// How far an obstacle moves before frames show it moved: 1/300 of a pixel at the default
// 640x480 view of a 1.9 m lot, under one level of a soft edge's colour.
constexpr double kShownPositionStep_m = 1e-5;
constexpr double kShownHeadingStep_rad = 1e-5;

// ffmpeg reads its arguments in the C locale: never "29,97".
std::string formatFps(double fps) { return formatGeneral(fps, 6); }

VideoOutcome runFfmpeg(const std::string& ffmpeg_name, const std::string& out_dir,
                       const std::string& frames_dir, double fps, int frames, bool gif) {
  VideoOutcome outcome;
  const std::string what = gif ? "GIF" : "video";
  const std::string final_path = out_dir + (gif ? "/episode.gif" : "/episode.mp4");
  if (frames == 0) {
    outcome.status = VideoStatus::kNoFrames;
    outcome.message = "no " + what + ": no frames were recorded";
    return outcome;
  }
  const std::string ffmpeg = findExecutable(ffmpeg_name);
  if (ffmpeg.empty()) {
    outcome.status = VideoStatus::kFfmpegMissing;
    outcome.message = "no " + what + ": '" + ffmpeg_name +
                      "' is not on PATH (install it, e.g. apt-get install ffmpeg); the frames "
                      "are in " +
                      frames_dir;
    return outcome;
  }
  // ffmpeg picks the container from the extension, so the partial file keeps it.
  const std::string partial = out_dir + (gif ? "/episode.partial.gif" : "/episode.partial.mp4");
  std::vector<std::string> args = {ffmpeg,         "-hide_banner", "-loglevel",
                                   "error",        "-y",           "-framerate",
                                   formatFps(fps), "-i",           frames_dir + "/%06d.png"};
  if (gif) {
    const std::string gif_fps = formatFps(std::min(fps, 15.0));
    args.insert(args.end(),
                {"-vf",
                 "fps=" + gif_fps +
                     ",scale='min(iw,800)':-2:flags=lanczos,split[a][b];[a]palettegen[p];"
                     "[b][p]paletteuse",
                 partial});
  } else {
    // libx264 with yuv420p needs even sizes: pad by a pixel when a size is odd.
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt",
                             "yuv420p", "-crf", "20", partial});
  }
  const std::string log = out_dir + "/ffmpeg.log";
  const ProcessResult run = runProcess(args, log);
  std::error_code ec;
  if (!run.ok()) {
    std::filesystem::remove(partial, ec);
    outcome.status = VideoStatus::kFfmpegFailed;
    outcome.message = "no " + what + ": " + run.error + " (see " + log + ")";
    return outcome;
  }
  std::filesystem::rename(partial, final_path, ec);
  if (ec) {
    outcome.status = VideoStatus::kFfmpegFailed;
    outcome.message = "no " + what + ": cannot rename " + partial + ": " + ec.message();
    return outcome;
  }
  outcome.status = VideoStatus::kWritten;
  outcome.path = final_path;
  outcome.message = what + ": " + final_path;
  return outcome;
}

// What the caller hands the drawing thread, in order: a plan to draw from now on, or a sample
// and the frames due from it.
struct DrawJob {
  std::optional<std::vector<Pose2>> planned;  // setPlan: the planned path, and the tree
  std::vector<Trajectory> tree;
  FrameInput input;
  bool extends_path = false;  // input.pose joins the driven path
  int first_frame = 0;        // frames first_frame .. first_frame + frames - 1 show input
  int frames = 0;
};

// What the caller may hand the drawing thread ahead of it: the simulation runs on while the GL
// context is made (~0.2 s; a 999-frame film's simulation takes ~0.08 s) and while frames are
// drawn, its memory bounded. A caller that found the queue full waits until it is half empty,
// so the two threads do not wake each other for every frame (a wake-up costs more than a
// frame's simulation).
constexpr std::size_t kMaxDrawJobs = 2048;
constexpr std::size_t kMaxDrawBytes = kMaxQueuedSampleBytes;

std::size_t bytesOf(const DrawJob& job) {
  std::size_t bytes = sizeof(DrawJob) + job.input.obstacle_poses.size() * sizeof(Pose2) +
                      job.input.contacts.size() * sizeof(int);
  if (job.planned) bytes += job.planned->size() * sizeof(Pose2);
  for (const Trajectory& edge : job.tree) bytes += edge.points.size() * sizeof(TrajectoryPoint);
  return bytes;
}

}  // namespace

struct FrameRecorder::Impl {
  Scenario scenario;
  FrameDef def;
  SceneStyle style;
  std::string frames_dir;
  std::string gl_description;
  std::unique_ptr<EncodeQueue> queue;

  // The caller's side: which frames are due, and what was last taken.
  std::optional<double> t0;
  int next_frame = 0;
  std::optional<FrameInput> last;
  std::optional<Pose2> last_executed;  // the driven path's last pose
  bool last_rendered = false;
  bool finished = false;

  // The drawing thread's side: it alone makes and uses the renderer, and keeps what frames show.
  RenderDef render_def;
  std::unique_ptr<Renderer> renderer;
  long lot_drawings = 0;  // the renderer's backdropsDrawn(), when it ended
  std::vector<Pose2> planned;
  std::vector<Trajectory> tree;
  std::vector<Pose2> executed;
  std::vector<Pose2> shown_obstacles;  // obstacle poses as drawn

  // Between the two.
  std::thread drawer;
  std::mutex mutex;
  std::condition_variable job_cv, room_cv, idle_cv, ready_cv;
  std::deque<DrawJob> jobs;
  std::size_t queued_bytes = 0;        // bytesOf the jobs
  bool caller_waiting = false;         // for room in the queue
  bool ready = false;                  // the renderer is made, or failed
  bool drawing = false;                // a job is being drawn
  std::atomic<bool> stopping = false;  // read while drawing: a recorder destroyed stops early
  std::exception_ptr draw_failure;     // the first error drawing; later jobs are dropped

  void post(DrawJob job);
  void drawLoop();
  void waitReady();  // until the renderer is made; throws when it could not be
  void draw(const DrawJob& job);
  void render(const FrameInput& in, int index);
  void waitDrawn();
  // waitDrawn for at most `timeout`; true when drawn.
  bool waitDrawnFor(std::chrono::milliseconds timeout);
  void stopDrawing();
  void throwIfFailed() {
    {
      std::lock_guard lock(mutex);
      if (draw_failure) std::rethrow_exception(draw_failure);
    }
    const std::string error = queue->error();
    if (!error.empty()) throw Error("frames: " + error);
  }
};

void FrameRecorder::Impl::post(DrawJob job) {
  const std::size_t bytes = bytesOf(job);
  {
    std::unique_lock lock(mutex);
    if (jobs.size() >= kMaxDrawJobs || queued_bytes >= kMaxDrawBytes) {
      caller_waiting = true;
      room_cv.wait(lock, [this] {
        return (jobs.size() <= kMaxDrawJobs / 2 && queued_bytes <= kMaxDrawBytes / 2) ||
               draw_failure;
      });
      caller_waiting = false;
    }
    if (draw_failure) std::rethrow_exception(draw_failure);
    jobs.push_back(std::move(job));
    queued_bytes += bytes;
  }
  job_cv.notify_one();
}

void FrameRecorder::Impl::drawLoop() {
  // The renderer ends on the thread that used it (its context is current there), and what
  // finish() reports of it is kept.
  struct ReleaseRenderer {
    Impl& m;
    ~ReleaseRenderer() {
      if (!m.renderer) return;
      m.lot_drawings = m.renderer->backdropsDrawn();
      m.renderer.reset();
    }
  } release{*this};
  pthread_setname_np(pthread_self(), "parksim-draw");  // for top -H and profilers
  std::exception_ptr failure;
  try {
    renderer = std::make_unique<Renderer>(render_def);
    gl_description = renderer->description();
  } catch (...) {
    failure = std::current_exception();
  }
  {
    std::lock_guard lock(mutex);
    ready = true;
    draw_failure = failure;
    if (failure) {
      jobs.clear();
      queued_bytes = 0;
    }
  }
  ready_cv.notify_all();
  room_cv.notify_all();
  idle_cv.notify_all();
  while (!failure) {
    DrawJob job;
    bool resume = false;  // the caller may go on
    {
      std::unique_lock lock(mutex);
      job_cv.wait(lock, [this] { return stopping || !jobs.empty(); });
      if (jobs.empty()) return;
      job = std::move(jobs.front());
      jobs.pop_front();
      queued_bytes -= bytesOf(job);
      drawing = true;
      resume =
          caller_waiting && jobs.size() <= kMaxDrawJobs / 2 && queued_bytes <= kMaxDrawBytes / 2;
    }
    if (resume) room_cv.notify_one();
    try {
      draw(job);
    } catch (...) {
      failure = std::current_exception();
    }
    bool idle = false;
    {
      std::lock_guard lock(mutex);
      drawing = false;
      if (failure) {
        draw_failure = failure;
        jobs.clear();
        queued_bytes = 0;
      }
      idle = jobs.empty();
    }
    if (failure) room_cv.notify_all();
    if (idle) idle_cv.notify_all();
  }
}

void FrameRecorder::Impl::waitReady() {
  std::unique_lock lock(mutex);
  ready_cv.wait(lock, [this] { return ready; });
  if (draw_failure) std::rethrow_exception(draw_failure);
}

void FrameRecorder::Impl::draw(const DrawJob& job) {
  if (job.planned) {
    planned = *job.planned;
    tree = job.tree;
  }
  if (job.extends_path) executed.push_back(job.input.pose);
  for (int k = 0; k < job.frames && !stopping; ++k) render(job.input, job.first_frame + k);
}

void FrameRecorder::Impl::waitDrawn() {
  std::unique_lock lock(mutex);
  idle_cv.wait(lock, [this] { return (jobs.empty() && !drawing) || draw_failure; });
  if (draw_failure) std::rethrow_exception(draw_failure);
}

bool FrameRecorder::Impl::waitDrawnFor(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex);
  const bool done = idle_cv.wait_for(lock, timeout,
                                     [this] { return (jobs.empty() && !drawing) || draw_failure; });
  if (draw_failure) std::rethrow_exception(draw_failure);
  return done;
}

void FrameRecorder::Impl::stopDrawing() {
  {
    std::lock_guard lock(mutex);
    stopping = true;
  }
  job_cv.notify_all();
  if (drawer.joinable()) drawer.join();
}

void FrameRecorder::Impl::render(const FrameInput& in, int index) {
  ViewState view;
  view.robot = in.pose;
  view.robot_steer_rad = in.steer_rad;
  view.reference = in.reference;
  // Resting bodies creep by nanometres in the simulation; an obstacle is drawn where it is once
  // it moved more than an invisible amount (kShownPositionStep_m), so the kept lot stays kept.
  if (in.obstacle_poses.size() != shown_obstacles.size()) {
    shown_obstacles = in.obstacle_poses;
  } else {
    for (std::size_t i = 0; i < shown_obstacles.size(); ++i) {
      const Pose2& now = in.obstacle_poses[i];
      if (positionDistance(shown_obstacles[i], now) > kShownPositionStep_m ||
          headingDistance(shown_obstacles[i], now) > kShownHeadingStep_rad) {
        shown_obstacles[i] = now;
      }
    }
  }
  view.obstacle_poses = shown_obstacles;
  view.contacts = in.contacts;
  view.planned_path = planned;
  view.executed_path = executed;
  if (def.show_tree) view.tree_edges = tree;
  view.overlay = Overlay{scenario.name, in.t_s, in.position_error_m, in.heading_error_rad};
  // The top view keeps the lot's pixels while only the robot moves (Renderer's backdrop); the
  // following 3D camera sees the lot from a new place every frame.
  const SceneLayers layers = buildSceneLayers(scenario, view, style);
  std::optional<Scene> whole;  // the 3D view's
  if (def.view != FrameView::kTop) {
    whole = layers.back;
    appendScene(*whole, layers.front);
  }

  std::unique_ptr<RgbaImage> image = queue->acquire();
  const CameraDef top{};
  if (def.view == FrameView::kTop && queue->takesChangedRows()) {
    // Only the rows the front changed are drawn, read back and compared: the encoder holds the
    // rest from the last frame.
    std::vector<RowSpan> changed;
    try {
      changed = renderer->renderChanges(layers.back, layers.front, top, *image, 0);
    } catch (...) {
      queue->release(std::move(image));
      throw;
    }
    if (changed.size() == 1 && changed[0] == RowSpan{0, image->height}) {
      queue->submit(framePathIn(frames_dir, index), std::move(image));
    } else {
      queue->submit(framePathIn(frames_dir, index), std::move(image), std::move(changed));
    }
    return;
  }
  try {
    switch (def.view) {
      case FrameView::kTop: renderer->renderInto(layers.back, layers.front, top, *image, 0); break;
      case FrameView::k3d: renderer->renderInto(*whole, def.camera_3d, *image, 0); break;
      case FrameView::kBoth:
        renderer->renderInto(layers.back, layers.front, top, *image, 0);
        renderer->renderInto(*whole, def.camera_3d, *image, def.width_px);
        break;
    }
  } catch (...) {
    queue->release(std::move(image));
    throw;
  }
  queue->submit(framePathIn(frames_dir, index), std::move(image));
}

FrameRecorder::FrameRecorder(const Scenario& scenario, const FrameDef& def)
    : impl_(std::make_unique<Impl>()) {
  if (!(def.fps > 0.0) || !std::isfinite(def.fps)) {
    throw Error("frames: fps must be positive, got " + formatFps(def.fps));
  }
  if (def.width_px <= 0 || def.height_px <= 0 || def.width_px > 8192 || def.height_px > 8192) {
    throw Error("frames: size must be between 1x1 and 8192x8192, got " +
                std::to_string(def.width_px) + "x" + std::to_string(def.height_px));
  }
  if (def.encode_threads < 1 || def.queue_depth < 1) {
    throw Error("frames: encode_threads and queue_depth must be at least 1");
  }
  checkFilmMemory(def);  // before the frames' directory is made
  impl_->scenario = scenario;
  impl_->def = def;
  impl_->style = def.style.scaled(styleScaleFor(def.height_px)).forRobot(scenario.robot);
  impl_->frames_dir = def.out_dir + "/frames";
  ensureDirectory(impl_->frames_dir);

  RenderDef& render_def = impl_->render_def;
  render_def.width_px = def.width_px;
  render_def.height_px = def.height_px;
  render_def.msaa_samples = def.msaa_samples;
  render_def.context = def.context;
  const int image_width = def.view == FrameView::kBoth ? 2 * def.width_px : def.width_px;
  const FilmBuffers buffers = filmBuffers(def);
  impl_->queue =
      std::make_unique<EncodeQueue>(def.encode_threads, buffers.images, image_width, def.height_px,
                                    def.png_compression, buffers.kept > 0);
  // Frames are drawn on a thread of their own, which first makes the renderer (loads the GL
  // libraries, compiles the shaders): the caller's simulation goes on meanwhile.
  impl_->drawer = std::thread([m = impl_.get()] { m->drawLoop(); });
}

FrameRecorder::~FrameRecorder() {
  if (!impl_) return;
  {
    std::lock_guard lock(impl_->mutex);
    impl_->jobs.clear();  // not drawn: finish() was not called, or failed
    impl_->queued_bytes = 0;
  }
  impl_->stopDrawing();
  if (impl_->queue) impl_->queue->stop();
}

void FrameRecorder::setPlan(const Trajectory& planned, std::span<const Trajectory> tree_edges) {
  if (impl_->finished) throw Error("frames: setPlan after finish");
  DrawJob job;
  job.planned = samplePath(planned, impl_->scenario.robot);
  job.tree.assign(tree_edges.begin(), tree_edges.end());
  impl_->post(std::move(job));
}

int FrameRecorder::addFrame(const FrameInput& input) {
  Impl& m = *impl_;
  if (m.finished) throw Error("frames: addFrame after finish");
  m.throwIfFailed();
  if (!std::isfinite(input.t_s)) throw Error("frames: sample time is not finite");
  if (m.last && input.t_s < m.last->t_s) {
    throw Error("frames: sample time went backwards (" + formatFps(input.t_s) + " s after " +
                formatFps(m.last->t_s) + " s)");
  }
  const double t0 = m.t0.value_or(input.t_s);
  // A frame is due once the sample reaches its time, give or take rounding of the caller's
  // clock (k * dt summed in floating point can fall a hair short of k / fps). Counted before
  // anything changes: past the limit, the recorder stays as it was.
  const double slack = 1e-6 / m.def.fps;
  DrawJob job;
  job.first_frame = m.next_frame;
  while (input.t_s + slack >= t0 + (m.next_frame + job.frames) / m.def.fps) {
    if (m.next_frame + job.frames >= m.def.max_frames) {
      throw Error("frames: more than the limit of " + std::to_string(m.def.max_frames) +
                  " frames (docs/limits.md)");
    }
    ++job.frames;
  }
  m.t0 = t0;
  m.next_frame += job.frames;
  // Extend the driven path only where the robot moved, so standing still adds nothing.
  job.extends_path = !m.last_executed || positionDistance(*m.last_executed, input.pose) > 5e-4 ||
                     headingDistance(*m.last_executed, input.pose) > 0.02;
  if (job.extends_path) m.last_executed = input.pose;
  m.last = input;
  m.last_rendered = job.frames > 0;
  const int due = job.frames;
  if (job.frames > 0 || job.extends_path) {
    job.input = input;
    m.post(std::move(job));
  }
  return due;
}

RecordingResult FrameRecorder::finish(const std::function<void(long written)>& progress) {
  Impl& m = *impl_;
  if (m.finished) throw Error("frames: finish called twice");
  m.finished = true;
  if (m.last && !m.last_rendered) {
    DrawJob job;
    job.input = *m.last;
    job.first_frame = m.next_frame++;
    job.frames = 1;
    m.post(std::move(job));
  }
  if (progress) {
    // A display only: what is written does not depend on when it is looked at.
    while (!m.waitDrawnFor(std::chrono::milliseconds(100))) progress(m.queue->written());
  } else {
    m.waitDrawn();
  }
  m.stopDrawing();
  m.waitReady();  // a recording without a sample never drew
  m.queue->drain();
  if (progress) progress(m.queue->written());
  m.queue->stop();
  m.throwIfFailed();
  removeFramesFrom(m.frames_dir, m.next_frame);

  RecordingResult result;
  result.frames = m.next_frame;
  result.lot_drawings = m.lot_drawings;
  result.frames_dir = m.frames_dir;
  result.message = std::to_string(result.frames) + " frames: " + m.frames_dir + "/" +
                   (result.frames > 0 ? "000000.png ..." : "(none)");
  if (m.def.video) {
    result.video =
        runFfmpeg(m.def.ffmpeg, m.def.out_dir, m.frames_dir, m.def.fps, result.frames, false);
    result.message += "\n" + result.video.message;
  }
  if (m.def.gif) {
    result.gif =
        runFfmpeg(m.def.ffmpeg, m.def.out_dir, m.frames_dir, m.def.fps, result.frames, true);
    result.message += "\n" + result.gif.message;
  }
  return result;
}

int FrameRecorder::frames() const { return impl_->next_frame; }

long FrameRecorder::framesWritten() const { return impl_->queue->written(); }

std::string FrameRecorder::glDescription() const {
  impl_->waitReady();
  return impl_->gl_description;
}

std::string FrameRecorder::framePath(int index) const {
  return framePathIn(impl_->frames_dir, index);
}

}  // namespace parksim
