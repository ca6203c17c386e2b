#pragma once
// A shared library loaded when first needed (dlopen), for dependencies only some runs use: the
// GL backends (libEGL, libOSMesa, and LLVM behind it) cost a process ~40 libraries to map and
// relocate at start-up even when it never renders, and OMPL (parksim/planner/steering/OmplApi.h)
// half of what remained. A library is never unloaded (RTLD_NODELETE: Mesa and LLVM do not survive
// being unloaded), so its functions stay valid after the handle is gone.

#include <optional>
#include <string>

namespace parksim {

class SharedLibrary {
 public:
  /// Loads `name` (a soname such as "libEGL.so.1", or a path). Throws EnvironmentError "WHAT:
  /// cannot load NAME (the loader's reason); HINT" when it cannot.
  SharedLibrary(const std::string& name, const std::string& what, const std::string& hint);
  /// The library when the process has already loaded it; loads nothing.
  static std::optional<SharedLibrary> ifLoaded(const std::string& name);
  ~SharedLibrary();

  SharedLibrary(SharedLibrary&& other) noexcept;
  SharedLibrary& operator=(SharedLibrary&& other) noexcept;
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  const std::string& name() const { return name_; }

  /// The address of `symbol`, or null when the library has none.
  void* find(const char* symbol) const;
  /// The function `symbol`, typed F (a function pointer type). Throws EnvironmentError naming the
  /// library and the symbol when it is missing.
  template <class F>
  F function(const char* symbol) const {
    // Object pointer to function pointer: POSIX guarantees dlsym's result converts.
    return reinterpret_cast<F>(require(symbol));
  }

 private:
  SharedLibrary(void* handle, std::string name, std::string what);
  void* require(const char* symbol) const;

  void* handle_ = nullptr;
  std::string name_;
  std::string what_;  // for error messages, e.g. "EGL"
};

}  // namespace parksim
