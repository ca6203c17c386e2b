#include "parksim/cli/OutputDir.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "parksim/cli/Progress.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/system/ChildProcess.h"

namespace parksim::cli {

namespace fs = std::filesystem;

namespace {

// Marks a directory parksim wrote, so a later command may replace it.
constexpr const char* kMarker = ".parksim-out";

// What parksim wrote before the marker existed; a directory holding only these is replaceable.
bool isParksimOutput(const std::string& name) {
  static const char* const names[] = {
      kMarker, "trajectory.csv", "plan.json", "executed.csv", "metrics.json", "report.html",
      "frames", "figures", "episode.mp4", "episode.gif", "ffmpeg.log", "bench.csv", "summary.md",
      "episode.partial.mp4", "episode.partial.gif",
      // parksim report
      "summary.csv", "success_matrix.png", "tracking_error.png", "plan_time.png", "path_length.png",
      "duration.png", "index.html", "parameters.csv"};
  for (const char* n : names) {
    if (name == n) return true;
  }
  const auto ends = [&](const std::string& s) {
    return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
  };
  return (name.rfind("plan_", 0) == 0 && ends(".json")) ||
         (name.rfind("ompl_", 0) == 0 && ends(".log")) ||
         (name.rfind("parameter_", 0) == 0 && ends(".png")) || ends(".tmp");
}

std::string errnoText() { return std::strerror(errno); }

// ".NAME" + suffix, built by appending (GCC 12 warns falsely on "." + name + "...").
std::string hidden(const std::string& name, const char* suffix) {
  std::string s(1, '.');
  s.append(name).append(suffix);
  return s;
}

}  // namespace

struct OutputDir::Impl {
  std::string shown_out;  // --out as the user wrote it
  fs::path out;           // absolute
  fs::path staging;
  std::string staging_text;  // staging as a string, for path()
  int lock_fd = -1;
  bool committed = false;
  std::mutex mutex;  // commit vs. the signal watcher
  std::atomic<bool> stop{false};
  std::atomic<bool> started{false};
  sigset_t old_mask{};
  std::thread watcher;

  // Waits for SIGINT, SIGTERM or SIGHUP (blocked in every thread made after the constructor),
  // removes the staging directory and dies of the signal as the default action would.
  void watch() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
    started.store(true);
    while (!stop.load()) {
      const timespec wait{0, 50'000'000};
      const int sig = sigtimedwait(&set, nullptr, &wait);
      if (sig <= 0) continue;
      {
        killChildProcessGroups();  // a planner or controller command, and what it started
        std::lock_guard<std::mutex> hold(mutex);
        if (!committed) {
          // Other threads (PNG encoders, the episode) may still be writing into it by path:
          // move it aside first, so that no entry can appear in it while it is removed.
          std::error_code ec;
          fs::path doomed = staging;
          doomed += ".removing";
          fs::rename(staging, doomed, ec);
          fs::remove_all(ec ? staging : doomed, ec);
        }
        endOpenProgressLine();  // a "planning: ..." line must not run into the prompt
        ::signal(sig, SIG_DFL);
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, sig);
        pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
        ::raise(sig);
      }
    }
  }
};

OutputDir::OutputDir(const std::string& out) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.shown_out = out;
  if (out.empty()) throw Error("--out: must not be empty");
  std::error_code ec;
  fs::path p = fs::absolute(out, ec).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();  // "dir/" -> "dir"
  std::error_code link_ec;
  if (!ec && fs::is_symlink(p, link_ec)) p = fs::canonical(p, ec);
  const std::string name = p.filename().string();
  if (ec || name.empty() || name == "." || name == ".." || p == p.root_path()) {
    throw Error("--out " + out + ": needs a directory name (not / or ..)");
  }
  m.out = p;
  const fs::path parent = p.parent_path();
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent)) {
    throw Error("--out " + out + ": cannot create " + parent.string() +
                (ec ? ": " + ec.message() : std::string()));
  }

  const std::string lock_path = (parent / hidden(name, ".lock")).string();
  m.lock_fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (m.lock_fd < 0)
    throw Error("--out " + out + ": cannot open " + lock_path + ": " + errnoText());
  if (::flock(m.lock_fd, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = errno == EWOULDBLOCK;
    const std::string why = errnoText();
    ::close(m.lock_fd);
    m.lock_fd = -1;
    throw Error("--out " + out + ": " +
                (busy ? "another parksim command is writing there (" + lock_path +
                            " is locked); wait for it or choose another --out"
                      : "cannot lock " + lock_path + ": " + why));
  }
  bool masked = false;
  try {
    if (fs::exists(fs::symlink_status(p, ec))) {
      if (!fs::is_directory(p, ec)) throw Error("--out " + out + ": exists and is not a directory");
      for (const fs::directory_entry& e : fs::directory_iterator(p, ec)) {
        const std::string entry = e.path().filename().string();
        if (!isParksimOutput(entry)) {
          throw Error("--out " + out + ": holds '" + entry +
                      "', which parksim did not write; choose an empty or new directory "
                      "(parksim replaces --out as a whole)");
        }
      }
      if (ec) throw Error("--out " + out + ": cannot list: " + ec.message());
    }
    // Leftovers of commands that were killed (SIGKILL cannot be cleaned up after).
    const std::string prefix = hidden(name, ".parksim-");
    for (const fs::directory_entry& e : fs::directory_iterator(parent, ec)) {
      if (e.path().filename().string().rfind(prefix, 0) == 0) fs::remove_all(e.path(), ec);
    }

    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
    pthread_sigmask(SIG_BLOCK, &set, &m.old_mask);
    masked = true;
    m.staging = parent / (prefix + "staging-" + std::to_string(::getpid()));
    m.staging_text = m.staging.string();
    if (!fs::create_directory(m.staging, ec) || ec) {
      throw Error("--out " + out + ": cannot create " + m.staging.string() +
                  (ec ? ": " + ec.message() : std::string()));
    }
    std::ofstream(m.staging / kMarker) << "written by parksim; the whole directory is replaced by "
                                          "the next parksim command writing here\n";
    // Only now: a signal that arrived while the staging directory was being made is pending
    // (blocked above) and the watcher removes a directory that exists, instead of racing
    // create_directory and leaving it behind.
    m.watcher = std::thread([&m] { m.watch(); });
    // Not before the watcher waits: a process for user code may be forked next
    // (usercode/UserCodeIsolation.h), and a thread still starting may hold the allocator's locks
    // (AddressSanitizer's allocator, before LLVM 17, takes none around fork), which the forked
    // child then waits for forever.
    while (!m.started.load()) std::this_thread::yield();
  } catch (...) {
    if (m.watcher.joinable()) {
      m.stop = true;
      m.watcher.join();
    }
    if (masked) pthread_sigmask(SIG_SETMASK, &m.old_mask, nullptr);
    if (!m.staging.empty()) fs::remove_all(m.staging, ec);
    ::close(m.lock_fd);
    throw;
  }
}

OutputDir::~OutputDir() {
  Impl& m = *impl_;
  m.stop = true;
  if (m.watcher.joinable()) m.watcher.join();
  std::error_code ec;
  if (!m.committed) fs::remove_all(m.staging, ec);
  pthread_sigmask(SIG_SETMASK, &m.old_mask, nullptr);
  ::close(m.lock_fd);  // releases the lock
}

const std::string& OutputDir::path() const { return impl_->staging_text; }

std::string OutputDir::shown(std::string text) const {
  const std::string from = impl_->staging.string();
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + impl_->shown_out.size())) {
    text.replace(at, from.size(), impl_->shown_out);
  }
  return text;
}

void OutputDir::commit() {
  Impl& m = *impl_;
  std::lock_guard<std::mutex> hold(m.mutex);
  const std::string staging = m.staging.string();
  const std::string out = m.out.string();
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(m.out, ec))) {
    if (::rename(staging.c_str(), out.c_str()) != 0) {
      throw Error("--out " + m.shown_out + ": cannot move the new outputs in: " + errnoText());
    }
  } else if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, out.c_str(), RENAME_EXCHANGE) != 0) {
    // File systems without an atomic exchange: two renames, --out briefly absent.
    if (errno != EINVAL && errno != ENOSYS) {
      throw Error("--out " + m.shown_out + ": cannot swap the new outputs in: " + errnoText());
    }
    const std::string old =
        (m.out.parent_path() /
         (hidden(m.out.filename().string(), ".parksim-old-") + std::to_string(::getpid())))
            .string();
    if (::rename(out.c_str(), old.c_str()) != 0 || ::rename(staging.c_str(), out.c_str()) != 0) {
      throw Error("--out " + m.shown_out + ": cannot swap the new outputs in: " + errnoText());
    }
    fs::remove_all(old, ec);
  }
  m.committed = true;
  fs::remove_all(m.staging, ec);  // after the exchange: the earlier outputs
}

}  // namespace parksim::cli
