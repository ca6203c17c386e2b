#pragma once
// A command's output directory as a transaction. Everything goes into a staging directory beside
// --out (same file system), which replaces --out in one atomic exchange at the end; until then
// --out keeps the earlier run's files untouched, and on error, SIGINT, SIGTERM or SIGHUP the
// staging directory is removed. An advisory lock (flock on .NAME.lock beside --out) makes a
// second command writing into the same --out fail at once.
//
// Usage, after every input has been read and checked:
//   OutputDir out(opt.out);                  // lock, staging; throws Error when busy
//   write files under out.path() ...
//   out.commit();                            // swap in; the old contents are removed
// A directory is only ever replaced when it is empty or holds nothing but parksim's outputs, so a
// mistyped --out (a home directory, a source tree) is refused instead of emptied.
//
// A SIGKILLed command cannot clean up: it leaves .NAME.parksim-staging-PID beside --out (never
// inside it), which the next command into the same --out removes.

#include <atomic>
#include <memory>
#include <string>

namespace parksim::cli {

class OutputDir {
 public:
  /// Locks `out`, removes stale staging directories of killed runs and creates a fresh staging
  /// directory. Throws Error when `out` exists and is not a parksim output directory, when
  /// another command holds the lock, or when the parent directory cannot be written.
  explicit OutputDir(const std::string& out);
  /// Without commit(): removes the staging directory; `out` stays as it was.
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  /// Where to write (the staging directory).
  const std::string& path() const;
  /// `text` with the staging path replaced by --out, for messages that name written files.
  std::string shown(std::string text) const;
  /// Makes the staging directory --out, atomically. Throws Error when it cannot.
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim::cli
