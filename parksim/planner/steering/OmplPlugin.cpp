#include "parksim/planner/steering/OmplPlugin.h"

namespace parksim {

OmplPlugin::OmplPlugin()
    : library_(kFileName, "OMPL plugin",
               "it is built and installed with parksim (lib/parksim/); if parksim was moved, "
               "add that directory to LD_LIBRARY_PATH"),
      api_(library_.function<const ParksimOmplApi* (*)()>(PARKSIM_OMPL_API_SYMBOL)()) {}

}  // namespace parksim
