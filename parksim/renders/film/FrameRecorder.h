#pragma once
// Films an episode: one PNG per 1/fps of simulated time in DIR/frames/000000.png, ...,
// optionally turned into DIR/episode.mp4 and/or DIR/episode.gif by ffmpeg at the end.
//
// Usage, from a simulation observer:
//   FrameRecorder rec(scenario, frame_def);
//   rec.setPlan(plan.trajectory);                 // optional: draws the planned path
//   for each sample: rec.addFrame(input);         // any rate; frames are taken at 1/fps
//   RecordingResult r = rec.finish();             // waits for the files; runs ffmpeg if asked
//   print r.message
//
// The GL context, framebuffers and image buffers are made once. Frames are drawn on a thread of
// the recorder's own, from the samples in the order given, while the caller simulates on; PNGs
// are encoded and written on worker threads while the next frame renders. File names come from
// the frame index, so the files and their bytes do not depend on the threading.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/renders/gl/OffscreenContext.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/scene/Camera.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

enum class FrameView {
  kTop,   ///< the top-down plan view
  k3d,    ///< the perspective view (FrameDef::camera_3d)
  kBoth,  ///< both, side by side in one image: top on the left, 3D on the right
};

const char* toString(FrameView view);
/// Parses "top", "3d" or "both"; throws Error otherwise.
FrameView frameViewFromString(const std::string& name);

struct ImageSize {
  int width_px = 0;
  int height_px = 0;
};

/// Parses "WxH" (e.g. "640x480"), each between 16 and 8192. Throws Error otherwise.
ImageSize parseImageSize(const std::string& text);

struct FrameDef {
  double fps = 30.0;    ///< frames per second of simulated time (> 0)
  int width_px = 640;   ///< width of one view, pixels; kBoth images are twice as wide
  int height_px = 480;  ///< pixels
  FrameView view = FrameView::kTop;
  std::string out_dir = "out";    ///< frames go to out_dir/frames/, videos to out_dir/
  bool video = false;             ///< finish() makes out_dir/episode.mp4 (libx264, yuv420p)
  bool gif = false;               ///< finish() makes out_dir/episode.gif (at most 15 frames/s)
  std::string ffmpeg = "ffmpeg";  ///< program name looked up on $PATH, or a path
  /// The 3D view's camera: by default it follows the robot from the south-south-east, 45 degrees
  /// above the ground.
  CameraDef camera_3d{.mode = CameraMode::kFollow,
                      .fov_y_deg = 45.0,
                      .azimuth_deg = -60.0,
                      .elevation_deg = 45.0,
                      .follow_distance_m = 0.6};
  /// Colours and widths for a 480-pixel-high image; scaled to height_px.
  SceneStyle style;
  bool show_tree = false;  ///< draw the planner's tree (setPlan) under the paths
  /// Anti-aliasing samples per pixel. 1 (the default) keeps frames fast: lines, text and the top
  /// view's edges are then smoothed by the renderer itself. 4 is full MSAA, about 3x slower on
  /// llvmpipe (docs/rendering.md).
  int msaa_samples = 1;
  /// PNG encoder threads (>= 1). One keeps a 2-core machine busy: the drawing thread renders
  /// while it encodes. A second one measured slower (more CPU per frame from contention).
  int encode_threads = 1;
  int queue_depth = 3;  ///< frames rendered ahead of the encoders (>= 1), memory allowing
  /// Memory for frames' pixels, bytes: the frames in flight (queue_depth + encode_threads at
  /// most) and, when two more fit, the encoders' copies of their last frame (which lets them copy
  /// unchanged bands and the top view read back only the rows that changed). Fewer frames are
  /// rendered ahead where they would need more; one is always in flight, so a film holds
  /// max(frame_memory_bytes, one frame) (filmBuffers, docs/limits.md). The bytes of the files do
  /// not depend on it.
  std::size_t frame_memory_bytes = std::size_t{512} << 20;
  /// PNG compression of the frames. kDefault (zlib level 1, chosen by measurement) is small
  /// (~25 kB a 640x480 frame); kFast (a run-length deflate) encodes in about 60 % of the CPU
  /// for files of about the same size on films, larger on busy images; both copy the bands of
  /// rows a frame shares with the last frame its encoder thread wrote. kStored writes the pixels
  /// uncompressed (0.92 MB a frame: on a disk, slower to write than to compress). The bytes depend
  /// on this setting, never on the threads. Numbers: docs/rendering.md.
  PngCompression png_compression = PngCompression::kDefault;
  /// Most frames one recording may write (docs/limits.md): 50,000 frames are ~28 min of
  /// simulated time at 30 fps and ~1.5 min of rendering at 640x480.
  int max_frames = 50'000;
  /// The OpenGL backend (default auto: PARKSIM_GL_BACKEND, else EGL, then OSMesa).
  ContextDef context;
};

/// The frames an episode of `duration_s` simulated seconds takes at def.fps (one per 1/fps and
/// the last sample). Throws Error naming fps, duration and def.max_frames when that is more.
double checkFrameLimits(const FrameDef& def, double duration_s);

/// The frames' pixels a recording holds (FrameDef::frame_memory_bytes).
struct FilmBuffers {
  /// One frame as drawn, RGBA: its width (twice width_px for kBoth) x height_px x 4 bytes.
  std::size_t frame_bytes = 0;
  int images = 1;  ///< frames in flight: drawn and waiting, or being encoded (>= 1)
  int kept = 0;    ///< last frames the encoders keep: encode_threads, or 0
  std::size_t bytes() const { return static_cast<std::size_t>(images + kept) * frame_bytes; }
};

/// How a recording made with `def` spends def.frame_memory_bytes: the encoders keep their last
/// frame when that and one frame in flight fit (kDefault and kFast only), then as many frames are
/// in flight as fit, from 1 to queue_depth + encode_threads.
FilmBuffers filmBuffers(const FrameDef& def);

/// Samples waiting for the drawing thread, bytes at most (besides a count limit).
constexpr std::size_t kMaxQueuedSampleBytes = std::size_t{32} << 20;
/// The most a film may hold, bytes, of what grows with its frame (filmPeakBytes): 2 GB less
/// 300 MB for the rest of the process (`parksim run` measured 110 to 160 MB), docs/limits.md.
constexpr std::size_t kFilmMemoryBoundBytes = 1'700'000'000;

/// What a recording made with `def` holds at most that grows with the frame, bytes: the
/// renderer's framebuffers (16 a pixel of one view at one sample; msaa_samples n > 1: 16n + 4),
/// filmBuffers(def).bytes(), each encoder's image-sized buffers (kStored: its whole file, 3 bytes
/// a pixel; kSmall: an RGB copy, stb's filtered image and its output, counted as 3 x 3 bytes a
/// pixel) and the queued samples. kDefault's and kFast's outputs (a few % of a frame) are not
/// counted: the bound leaves room for them.
std::size_t filmPeakBytes(const FrameDef& def);

/// Throws Error, one line naming the size, view, compression, msaa_samples, encode_threads,
/// the computed bytes and kFilmMemoryBoundBytes, when filmPeakBytes(def) exceeds that bound.
void checkFilmMemory(const FrameDef& def);

/// One simulation sample, as plain data (mirrors sim's EpisodeSample).
struct FrameInput {
  double t_s = 0.0;                ///< simulated time, s; non-decreasing across calls
  Pose2 pose;                      ///< executed pose of the reference point
  double steer_rad = 0.0;          ///< a car's measured steering angle: its front wheels turn
  std::optional<Pose2> reference;  ///< planned pose at t_s: drawn as an outline
  double position_error_m = 0.0;   ///< shown in the overlay
  double heading_error_rad = 0.0;  ///< shown in the overlay
  /// Box centre and yaw per obstacle; empty: as in the scenario. An obstacle is drawn anew
  /// once it moved over 10 um or 1e-5 rad from where frames last showed it: resting bodies
  /// creep by nanometres, which no pixel shows.
  std::vector<Pose2> obstacle_poses;
  std::vector<int> contacts;  ///< obstacles touching the robot (scenario order)
};

enum class VideoStatus {
  kNotRequested,
  kWritten,
  kFfmpegMissing,  ///< ffmpeg is not on $PATH: frames are there, no video
  kFfmpegFailed,   ///< ffmpeg ran and failed; see DIR/ffmpeg.log
  kNoFrames,       ///< nothing to encode
};

struct VideoOutcome {
  VideoStatus status = VideoStatus::kNotRequested;
  std::string path;     ///< the file, when written
  std::string message;  ///< one line for the user; empty when not requested
};

struct RecordingResult {
  int frames = 0;  ///< PNG files written
  /// Times the top view's lot was drawn, not kept from the frame before: 1 when no obstacle
  /// moved or was touched (0 for the 3D view alone).
  long lot_drawings = 0;
  std::string frames_dir;  ///< DIR/frames
  VideoOutcome video;      ///< episode.mp4
  VideoOutcome gif;        ///< episode.gif
  /// One line per outcome, ready to print: frames, then video and gif when requested.
  std::string message;
};

class FrameRecorder {
 public:
  /// Creates DIR/frames and the encoder threads, and starts the drawing thread, which first
  /// makes the renderer (GL context, shaders) while the caller goes on. Frames of an earlier
  /// recording into the same directory are overwritten, and finish() removes those beyond this
  /// one's. Throws Error on a bad definition or an unwritable directory; when no GL context can
  /// be made, the next call after the drawing thread found it out throws that error
  /// (EnvironmentError): addFrame, setPlan, glDescription or finish.
  FrameRecorder(const Scenario& scenario, const FrameDef& def);
  /// Drops the samples not drawn yet and waits for the frames being written (errors are
  /// dropped): without finish(), which frames exist depends on timing. Call finish() for a
  /// whole film and its errors.
  ~FrameRecorder();

  FrameRecorder(const FrameRecorder&) = delete;
  FrameRecorder& operator=(const FrameRecorder&) = delete;

  /// The planned path (drawn in every frame) and the tree's edges (drawn when show_tree).
  /// Frames due after this call show it. Throws Error after finish(), or the drawing thread's
  /// error (as addFrame).
  void setPlan(const Trajectory& planned, std::span<const Trajectory> tree_edges = {});

  /// Takes one sample. Frames are due at t0 + k / fps, t0 being the first sample's time; every
  /// due frame up to this sample's time is rendered from it (a sparse caller gets repeated
  /// frames, a dense one has samples skipped). Returns the number of frames due from it, which
  /// the drawing thread draws. Throws Error when t_s goes backwards or is not finite, or when an
  /// earlier frame could not be drawn or written.
  int addFrame(const FrameInput& input);

  /// Renders the last sample if it came after the last frame (so the film ends at the final
  /// pose), waits until every PNG is written, removes frame files an earlier, longer recording
  /// left behind, then runs ffmpeg when video or gif is set. A
  /// missing or failing ffmpeg is reported in the result, not thrown. Throws Error when a frame
  /// could not be drawn or written, or no GL context could be made (EnvironmentError). Call
  /// once; addFrame afterwards throws. `progress`, when given, is called on this thread with
  /// the frames written so far while it waits for the drawing (about ten times a second), and
  /// once more when the encoders are done (then with all frames, unless one failed to write).
  RecordingResult finish(const std::function<void(long written)>& progress = {});

  /// Frames due so far: drawn, or handed to the drawing thread.
  int frames() const;
  /// Frames drawn and written so far (the drawing thread may be well behind frames()).
  long framesWritten() const;
  /// The GL context's description (Renderer::description), for provenance.
  std::string glDescription() const;
  /// Path of frame `index`: DIR/frames/%06d.png.
  std::string framePath(int index) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
