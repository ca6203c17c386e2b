#pragma once
// Reading an input file whole, within a size limit. Only regular files are read: a directory,
// a device (/dev/zero, /dev/urandom), a pipe or a socket is refused before a byte is read, and
// a file larger than the limit is refused by its size, so no input makes a reader's memory or
// time grow without bound.

#include <cstddef>
#include <cstdint>
#include <string>

namespace parksim {

/// The bytes of the regular file at `path`, at most `max_bytes` of them. Throws Error with one
/// line "<path>: <what> ..." when the file cannot be opened, is not a regular file, or is
/// larger than `max_bytes` (the message states the limit), or "cannot open <what>: the path is
/// empty". `what` names the kind of file ("plan file", "world file").
std::string readInputFile(const std::string& path, std::uintmax_t max_bytes, const char* what);

/// The first `head_bytes` bytes of the regular file at `path` (all of it when shorter), with
/// readInputFile's checks but whatever the file's size: for a reader whose header alone
/// decides whether the file is within its limits, before the file is read whole.
std::string readInputFileHead(const std::string& path, std::size_t head_bytes, const char* what);

}  // namespace parksim
