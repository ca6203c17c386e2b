#pragma once
// Python objects as planners and controllers (UserCodeBindings.cpp).

#include <string>

#include "parksim/usercode/Components.h"
#include "python/src/Bindings.h"

namespace parksim::python {

/// Takes `plugins` (paths), and a `planner` or `controller` that is a Python object rather than
/// a name, from `options`: the request's components become parksim's own, the plugins' and
/// those objects (registered under their names, as untrusted user code), and `planner` /
/// `controller` are left in `options` as those names.
void takeComponents(py::dict& options, EpisodeRequest& request);

/// Registers a Python planner (an object with solve(problem)) under `name` (empty: its own
/// name attribute, else its __name__ or class name); returns the name.
std::string addPythonPlanner(Components& components, const py::object& planner,
                             const std::string& name = "");
/// Registers a Python controller (a callable, or an object with command() and maybe reset())
/// likewise; returns its name.
std::string addPythonController(Components& components, const py::object& controller,
                                const std::string& name = "");

}  // namespace parksim::python
