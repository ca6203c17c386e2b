#pragma once
// Internal to parksim_render (not installed). The PNG encoder threads of a film: images travel from
// the drawing thread to the encoders and back through a fixed pool, so a steady recording allocates
// nothing per frame and never runs more than its depth ahead. Each encoder keeps its PngEncoder
// (zlib state, the last image's bands) for every frame it writes.

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "parksim/renders/image/Image.h"
#include "parksim/renders/image/PngEncoder.h"

namespace parksim {

class EncodeQueue {
 public:
  /// `threads` encoders; `depth` images of width x height in the pool. `keep_last`: each
  /// encoder keeps the last image it wrote (PngEncoder's keep_last_image), one more image each.
  EncodeQueue(int threads, int depth, int width, int height, PngCompression png, bool keep_last);
  ~EncodeQueue();
  EncodeQueue(const EncodeQueue&) = delete;
  EncodeQueue& operator=(const EncodeQueue&) = delete;

  /// An image from the pool to draw into; waits while all are in use.
  std::unique_ptr<RgbaImage> acquire();
  /// Encodes `image` to `path` on an encoder thread; the image then returns to the pool.
  void submit(std::string path, std::unique_ptr<RgbaImage> image);
  /// Whether submit may say which rows changed: one encoder, so it encodes the frames in order,
  /// with a compression that keeps the last image, and keeps it (PngEncoder::encode with rows).
  bool takesChangedRows() const { return takes_changed_rows_; }
  /// submit for the frame after the last one submitted, of which only rows `changed` are
  /// valid in `image`: the others are the last frame's. Only when takesChangedRows().
  void submit(std::string path, std::unique_ptr<RgbaImage> image, std::vector<RowSpan> changed);
  /// Puts back an image acquired and not submitted.
  void release(std::unique_ptr<RgbaImage> image);
  /// Blocks until every submitted frame is written.
  void drain();
  /// Writes what was submitted, then ends the threads.
  void stop();
  /// The first write error, if any.
  std::string error() const;
  /// Frames written so far.
  long written() const;

 private:
  struct Job {
    std::string path;
    std::unique_ptr<RgbaImage> image;
    std::optional<std::vector<RowSpan>> changed;  // unset: the whole image
  };

  void push(Job job);
  void work(PngCompression png, bool keep_last);

  mutable std::mutex mutex_;
  std::condition_variable job_cv_, free_cv_, idle_cv_;
  std::deque<Job> jobs_;
  std::vector<std::unique_ptr<RgbaImage>> free_;
  std::vector<std::thread> workers_;
  bool takes_changed_rows_ = false;
  long written_ = 0;
  int busy_ = 0;
  bool stopping_ = false;
  std::string error_;
};

}  // namespace parksim
