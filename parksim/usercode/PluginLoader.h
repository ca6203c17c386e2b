#pragma once
// Loads a plugin (PluginApi.h) into a Components: checks its entry point, API version and type
// layout before calling anything else in it, registers what it adds, records it.

#include <string>
#include <vector>

#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/usercode/Components.h"

namespace parksim {

/// Loads the shared library at `path` and registers its planners and controllers in
/// `components`. Throws Error, one line naming the file, when it cannot be read or loaded, has
/// no entry point, was built against another plugin API version or type layout, registers
/// nothing, or registers a name already taken (nothing of it is registered then). Loading the
/// same file twice is an error too. The plugin is loaded first in a child process, so a crash
/// or a hang while it loads is such an Error too: a child still loading after `load_limit_s`
/// (in [UserCodeLimits::kMin, kMax]) is killed with its process group.
const PluginRecord& loadPlugin(Components& components, const std::string& path,
                               double load_limit_s = UserCodeLimits::kPluginLoadS);

/// Built-ins plus every plugin in `paths`, in order.
std::shared_ptr<const Components> loadComponents(const std::vector<std::string>& paths);

/// FNV-1a 64 of a file's bytes as 16 hex digits; throws Error naming the file when it cannot be
/// read.
std::string fileHash(const std::string& path);

}  // namespace parksim
