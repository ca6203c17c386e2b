#pragma once
// Writes a whole file or nothing: content goes to a temporary file beside the target, which is
// renamed over it only once it is complete.

#include <string>
#include <string_view>

namespace parksim {

/// Throws Error ("path: reason") when the file cannot be written.
void writeFileAtomically(const std::string& path, std::string_view content);

/// Creates a directory and its parents if missing. Throws Error on failure.
void ensureDirectory(const std::string& path);

}  // namespace parksim
