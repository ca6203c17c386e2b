#pragma once
// What the sweep-table harnesses share: the fuzz input as a file (a memfd, so the readers' own
// file path is exercised: open, fstat, line reading) and a scratch directory in /dev/shm.

#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace parksim::fuzz {

/// A file in memory holding `bytes`; its path is /proc/self/fd/N.
class MemFile {
 public:
  explicit MemFile(std::string_view bytes) : fd_(::memfd_create("fuzz", MFD_CLOEXEC)) {
    if (fd_ < 0) std::abort();
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (n <= 0) std::abort();
      done += static_cast<std::size_t>(n);
    }
  }
  ~MemFile() { ::close(fd_); }
  MemFile(const MemFile&) = delete;
  MemFile& operator=(const MemFile&) = delete;
  std::string path() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  int fd_;
};

/// Writes `bytes` to `path` (truncating).
inline void writeFile(const std::string& path, std::string_view bytes) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) std::abort();
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) std::abort();
  std::fclose(f);
}

/// A directory for the harness's files: $PARKSIM_FUZZ_SCRATCH (scripts/fuzz.sh makes one in
/// /dev/shm and removes it), else one of this process under /tmp. Made once.
inline const std::string& scratchDir() {
  static const std::string dir = [] {
    const char* given = std::getenv("PARKSIM_FUZZ_SCRATCH");
    std::string d = given != nullptr && *given != '\0'
                        ? std::string(given) + "/" + std::to_string(::getpid())
                        : "/tmp/parksim-fuzz-" + std::to_string(::getpid());
    if (::mkdir(d.c_str(), 0700) != 0 && errno != EEXIST) std::abort();
    return d;
  }();
  return dir;
}

}  // namespace parksim::fuzz
