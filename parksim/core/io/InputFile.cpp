#include "parksim/core/io/InputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

// Closes the descriptor on every way out; moved, not copied.
struct Fd {
  int fd;
  explicit Fd(int f) : fd(f) {}
  Fd(Fd&& o) noexcept : fd(o.fd) { o.fd = -1; }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  Fd& operator=(Fd&&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// The regular file at `path`, opened for reading, and its size.
Fd openRegular(const std::string& path, const char* what, std::uintmax_t& size) {
  if (path.empty()) throw Error(std::string("cannot open ") + what + ": the path is empty");
  // O_NONBLOCK: opening a FIFO without a writer must not wait forever.
  Fd f{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)};
  if (f.fd < 0) {
    throw Error(path + ": cannot open " + what + ": " + std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) {
    throw Error(path + ": cannot read " + what + ": " + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) throw Error(path + ": is a directory, not a " + what);
  if (!S_ISREG(st.st_mode)) {
    throw Error(path + ": is not a regular file (a device, pipe or socket), not a " + what);
  }
  size = static_cast<std::uintmax_t>(st.st_size);
  return f;
}

// Reads into bytes[got, bytes.size()) until it is full or the file ends; returns the new count.
std::size_t readInto(const Fd& f, std::string& bytes, std::size_t got, const std::string& path,
                     const char* what) {
  while (got < bytes.size()) {
    const ssize_t n = ::read(f.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) throw Error(path + ": cannot read " + what + ": " + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  return got;
}

}  // namespace

std::string readInputFileHead(const std::string& path, std::size_t head_bytes, const char* what) {
  std::uintmax_t size = 0;
  const Fd f = openRegular(path, what, size);
  std::string bytes(head_bytes, '\0');
  bytes.resize(readInto(f, bytes, 0, path, what));
  return bytes;
}

std::string readInputFile(const std::string& path, std::uintmax_t max_bytes, const char* what) {
  std::uintmax_t size = 0;
  const Fd f = openRegular(path, what, size);
  const auto too_big = [&](std::uintmax_t size) {
    return Error(path + ": " + what + " is " + std::to_string(size) +
                 " bytes, more than the limit of " + std::to_string(max_bytes) +
                 " (docs/limits.md)");
  };
  if (size > max_bytes) throw too_big(size);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t got = readInto(f, bytes, 0, path, what);
  // The file may have grown since fstat: read on, one byte past the limit at most.
  while (got == bytes.size()) {
    if (bytes.size() > max_bytes) throw too_big(bytes.size());
    bytes.resize(std::min<std::uintmax_t>(max_bytes + 1, bytes.size() + 65536));
    got = readInto(f, bytes, got, path, what);
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace parksim
