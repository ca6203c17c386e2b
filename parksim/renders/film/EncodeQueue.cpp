#include "parksim/renders/film/EncodeQueue.h"

#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <span>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

// Frames are written in place, not through a temporary file and a rename as other outputs are:
// creating a file costs ~0.6 ms of kernel time on an ext4 that has seen many files come and go
// (its inode search skips recently deleted inodes), rewriting one that exists ~0.05 ms, and a
// rename always creates. So a second recording into the same directory rewrites its frames. A
// frame is never left half-written unless the process dies while writing it.
void writeFrame(const std::string& path, std::span<const unsigned char> bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw Error(path + ": cannot write: " + std::strerror(errno));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = std::strerror(errno);
      ::close(fd);
      ::unlink(path.c_str());
      throw Error(path + ": write failed: " + reason);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(path.c_str());
    throw Error(path + ": write failed: " + reason);
  }
}

}  // namespace

EncodeQueue::EncodeQueue(int threads, int depth, int width, int height, PngCompression png,
                         bool keep_last)
    : takes_changed_rows_(threads == 1 && keep_last && keepsLastImage(png)) {
  for (int i = 0; i < depth; ++i) free_.push_back(std::make_unique<RgbaImage>(width, height));
  for (int i = 0; i < threads; ++i) {
    workers_.emplace_back([this, png, keep_last] { work(png, keep_last); });
  }
}

EncodeQueue::~EncodeQueue() { stop(); }

std::unique_ptr<RgbaImage> EncodeQueue::acquire() {
  std::unique_lock lock(mutex_);
  free_cv_.wait(lock, [this] { return !free_.empty(); });
  std::unique_ptr<RgbaImage> image = std::move(free_.back());
  free_.pop_back();
  return image;
}

void EncodeQueue::submit(std::string path, std::unique_ptr<RgbaImage> image) {
  push({std::move(path), std::move(image), std::nullopt});
}

void EncodeQueue::submit(std::string path, std::unique_ptr<RgbaImage> image,
                         std::vector<RowSpan> changed) {
  if (!takes_changed_rows_) {
    release(std::move(image));
    throw Error("frames: this encoder takes whole images only");
  }
  push({std::move(path), std::move(image), std::move(changed)});
}

void EncodeQueue::push(Job job) {
  {
    std::lock_guard lock(mutex_);
    jobs_.push_back(std::move(job));
  }
  job_cv_.notify_one();
}

void EncodeQueue::release(std::unique_ptr<RgbaImage> image) {
  {
    std::lock_guard lock(mutex_);
    free_.push_back(std::move(image));
  }
  free_cv_.notify_one();
}

void EncodeQueue::drain() {
  std::unique_lock lock(mutex_);
  idle_cv_.wait(lock, [this] { return jobs_.empty() && busy_ == 0; });
}

void EncodeQueue::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  job_cv_.notify_all();
  for (std::thread& t : workers_) {
    if (t.joinable()) t.join();
  }
}

long EncodeQueue::written() const {
  std::lock_guard lock(mutex_);
  return written_;
}

std::string EncodeQueue::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void EncodeQueue::work(PngCompression png, bool keep_last) {
  pthread_setname_np(pthread_self(), "parksim-png");  // for top -H and profilers
  // One encoder per thread: its zlib state and buffers serve every frame.
  PngEncoder encoder(png, keep_last);
  while (true) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      job_cv_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
      if (jobs_.empty()) return;  // stopping, and nothing left to write
      job = std::move(jobs_.front());
      jobs_.pop_front();
      ++busy_;
    }
    std::string failure;
    try {
      writeFrame(job.path, job.changed ? encoder.encode(*job.image, *job.changed)
                                       : encoder.encode(*job.image));
    } catch (const std::exception& e) {
      failure = e.what();
    }
    {
      std::lock_guard lock(mutex_);
      if (!failure.empty() && error_.empty()) error_ = failure;
      if (failure.empty()) ++written_;
      free_.push_back(std::move(job.image));
      --busy_;
    }
    free_cv_.notify_one();
    idle_cv_.notify_all();
  }
}

}  // namespace parksim
