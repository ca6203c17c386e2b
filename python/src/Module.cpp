// parksim._parksim: the compiled part of the Python package `parksim` (python/parksim/ holds
// the rest). parksim::Error becomes parksim.Error, a ValueError with the same one-line message.

#include "parksim/core/io/Error.h"
#include "python/src/Bindings.h"

PYBIND11_MODULE(_parksim, m) {
  namespace py = pybind11;
  using namespace parksim::python;
  m.doc() = "parksim's C++ core: worlds, planning, episodes, rendering.";
  py::register_exception<parksim::Error>(m, "Error", PyExc_ValueError);
  bindRobot(m);
  bindDefs(m);
  bindWorld(m);
  bindPlan(m);
  bindEpisode(m);
  bindRender(m);
  bindTasks(m);
  bindUserCode(m);
  bindSweep(m);
}
