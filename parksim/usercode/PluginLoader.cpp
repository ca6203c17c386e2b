#include "parksim/usercode/PluginLoader.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <utility>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Fnv1a.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/system/ChildProcess.h"
#include "parksim/core/system/SharedLibrary.h"
#include "parksim/usercode/PluginApi.h"

namespace parksim {

std::shared_ptr<const Components> builtInComponents() {
  static const std::shared_ptr<const Components> components = std::make_shared<Components>();
  return components;
}

std::string fileHash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be read");
  std::uint64_t h = kFnv1a64Offset;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    h = fnv1a64(std::string_view(buffer, static_cast<std::size_t>(in.gcount())), h);
  }
  if (in.bad()) throw Error(path + ": cannot be read");
  return hex16(h);
}

namespace {

// Registers into a staged copy of the components, so that a plugin that fails halfway leaves
// nothing of itself behind.
class StagingRegistrar : public PluginRegistrar {
 public:
  StagingRegistrar(Components& staged, PluginRecord& record) : staged_(staged), record_(record) {}

  void addPlanner(PlannerEntry entry) override {
    const std::string name = entry.info.name;
    staged_.planners.add(std::move(entry), record_.name);
    record_.planners.push_back(name);
  }
  void addController(ControllerEntry entry) override {
    const std::string name = entry.info.name;
    staged_.controllers.add(std::move(entry), record_.name);
    record_.controllers.push_back(name);
  }

 private:
  Components& staged_;
  PluginRecord& record_;
};

std::string text(const char* s, const std::string& what, const std::string& file) {
  if (s == nullptr || !isPrintableUtf8(s) || std::string(s).empty() || std::string(s).size() > 64) {
    throw Error(file + ": the plugin's " + what + " is not 1 to 64 printable characters");
  }
  return s;
}

const PluginRecord& loadInThisProcess(Components& components, const std::string& path,
                                      const std::string& file);

// "SIGSEGV, Segmentation fault".
std::string probeSignalText(int sig) {
  const char* name = sigabbrev_np(sig);
  const char* what = strsignal(sig);
  return std::string("SIG") + (name != nullptr ? name : std::to_string(sig).c_str()) +
         (what != nullptr ? std::string(", ") + what : std::string());
}

// A plugin's static initializers, entry point and registration run when it is loaded, before
// parksim can watch them: a crash there would end the process loading it without a word, a hang
// would hang it. So it is loaded first in a forked child (which only loads it, into a scratch
// Components, and exits), in a process group of its own that is killed when it is not done
// within `limit_s`, and only a child that exited normally lets it be loaded here. What the
// child refuses, the load here refuses again with its message. Its output goes to /dev/null:
// what the plugin prints at load appears once, from the load here.
void probeLoad(const std::string& path, const std::string& file, double limit_s) {
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw Error(path + ": cannot probe the plugin: fork: " + std::strerror(errno));
  if (pid == 0) {
    ::setpgid(0, 0);
    resetForkedChild(parent);  // dies with the thread that forked it
    // The child: die of what kills it (not of a handler the parent installed), quietly.
    for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, SIG_DFL);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    try {
      Components scratch;
      loadInThisProcess(scratch, path, file);
    } catch (...) {  // refused: the load in the parent says why
    }
    ::_exit(0);  // no exit handlers: they are the parent's
  }
  ::setpgid(pid, pid);  // also here: whichever runs first
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  int status = 0;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) {
      const std::string why = std::strerror(errno);
      ::kill(-pid, SIGKILL);
      throw Error(path + ": cannot probe the plugin: waitpid: " + why);
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      ::kill(-pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      throw Error(path + ": the plugin did not finish loading within " + formatGeneral(limit_s) +
                  " s (its process was killed: its static initializers, entry point or "
                  "registration hang); not loaded");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFSIGNALED(status)) {
    throw Error(path + ": the plugin crashed while it was loaded (" +
                probeSignalText(WTERMSIG(status)) +
                ": in its static initializers, entry point or registration); not loaded");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw Error(path + ": the plugin ended the process while it was loaded (exit status " +
                std::to_string(WEXITSTATUS(status)) + "); not loaded");
  }
}

}  // namespace

const PluginRecord& loadPlugin(Components& components, const std::string& path,
                               double load_limit_s) {
  if (!(load_limit_s >= UserCodeLimits::kMin && load_limit_s <= UserCodeLimits::kMax)) {
    throw Error(path + ": plugin load time limit: must be in [" +
                formatGeneral(UserCodeLimits::kMin) + ", " + formatGeneral(UserCodeLimits::kMax) +
                "] s, got " + formatGeneral(load_limit_s));
  }
  std::error_code ec;
  const std::string file = std::filesystem::absolute(path, ec).lexically_normal().string();
  if (ec || !std::filesystem::is_regular_file(file, ec)) {
    throw Error(path + ": no such plugin file");
  }
  for (const PluginRecord& r : components.plugins) {
    if (r.path == file) throw Error(path + ": plugin loaded twice");
  }
  probeLoad(path, file, load_limit_s);
  return loadInThisProcess(components, path, file);
}

namespace {

const PluginRecord& loadInThisProcess(Components& components, const std::string& path,
                                      const std::string& file) {
  PluginRecord record;
  record.path = file;
  record.hash = fileHash(file);
  void* entry = nullptr;
  try {
    const SharedLibrary library(file, "plugin", "");
    entry = library.find(kPluginEntryPoint);
  } catch (const EnvironmentError& e) {
    // The user's file, not the machine: bad input.
    throw Error(e.what());
  }
  if (entry == nullptr) {
    throw Error(path + ": not a parksim plugin (no " + kPluginEntryPoint +
                " entry point; define one with PARKSIM_PLUGIN, parksim/usercode/PluginApi.h)");
  }
  // The library stays loaded (RTLD_NODELETE), so its functions outlive the handle.
  using EntryPoint = const PluginDescriptor* (*)();
  const PluginDescriptor* d = reinterpret_cast<EntryPoint>(entry)();
  if (d == nullptr) throw Error(path + ": the plugin's entry point returned nothing");
  if (d->api_version != PARKSIM_PLUGIN_API_VERSION) {
    throw Error(path + ": built against plugin API " + std::to_string(d->api_version) +
                ", this parksim has " + std::to_string(PARKSIM_PLUGIN_API_VERSION) +
                "; rebuild the plugin against this parksim");
  }
  if (d->abi_fingerprint != pluginAbiFingerprint()) {
    throw Error(path +
                ": built against parksim headers whose types differ from this parksim's "
                "(another build or compiler); rebuild the plugin against this parksim");
  }
  record.name = text(d->name, "name", path);
  record.version = text(d->version, "version", path);
  for (const PluginRecord& r : components.plugins) {
    if (r.name == record.name) {
      throw Error(path + ": a plugin named " + record.name + " is already loaded from " + r.path);
    }
  }
  if (d->register_components == nullptr) throw Error(path + ": the plugin registers nothing");
  Components staged = components;
  StagingRegistrar registrar(staged, record);
  try {
    d->register_components(registrar);
  } catch (const std::exception& e) {
    throw Error(path + ": plugin " + record.name + " failed to register: " + e.what());
  } catch (...) {
    throw Error(path + ": plugin " + record.name + " failed to register");
  }
  if (record.planners.empty() && record.controllers.empty()) {
    throw Error(path + ": plugin " + record.name + " registered no planner or controller");
  }
  staged.plugins.push_back(std::move(record));
  components = std::move(staged);
  return components.plugins.back();
}

}  // namespace

std::shared_ptr<const Components> loadComponents(const std::vector<std::string>& paths) {
  if (paths.empty()) return builtInComponents();
  auto components = std::make_shared<Components>();
  for (const std::string& path : paths) loadPlugin(*components, path);
  return components;
}

}  // namespace parksim
