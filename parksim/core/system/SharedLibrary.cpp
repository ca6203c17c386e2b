#include "parksim/core/system/SharedLibrary.h"

#include <dlfcn.h>

#include <utility>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

std::string loaderError() {
  const char* e = dlerror();
  return e != nullptr ? e : "unknown reason";
}

}  // namespace

SharedLibrary::SharedLibrary(void* handle, std::string name, std::string what)
    : handle_(handle), name_(std::move(name)), what_(std::move(what)) {}

SharedLibrary::SharedLibrary(const std::string& name, const std::string& what,
                             const std::string& hint)
    : name_(name), what_(what) {
  handle_ = dlopen(name.c_str(), RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE);
  if (handle_ == nullptr) {
    throw EnvironmentError(what + ": cannot load " + name + " (" + loaderError() + ")" +
                           (hint.empty() ? "" : "; " + hint));
  }
}

std::optional<SharedLibrary> SharedLibrary::ifLoaded(const std::string& name) {
  void* handle = dlopen(name.c_str(), RTLD_LAZY | RTLD_LOCAL | RTLD_NOLOAD);
  if (handle == nullptr) {
    dlerror();  // clear the loader's message: not loaded is an answer, not a failure
    return std::nullopt;
  }
  return SharedLibrary(handle, name, name);
}

SharedLibrary::~SharedLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
}

SharedLibrary::SharedLibrary(SharedLibrary&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)),
      name_(std::move(other.name_)),
      what_(std::move(other.what_)) {}

SharedLibrary& SharedLibrary::operator=(SharedLibrary&& other) noexcept {
  if (this != &other) {
    if (handle_ != nullptr) dlclose(handle_);
    handle_ = std::exchange(other.handle_, nullptr);
    name_ = std::move(other.name_);
    what_ = std::move(other.what_);
  }
  return *this;
}

void* SharedLibrary::find(const char* symbol) const {
  return handle_ != nullptr ? dlsym(handle_, symbol) : nullptr;
}

void* SharedLibrary::require(const char* symbol) const {
  void* address = find(symbol);
  if (address == nullptr) {
    throw EnvironmentError(what_ + ": " + name_ + " has no " + symbol);
  }
  return address;
}

}  // namespace parksim
