// Placeholder until the run command lands; its owner replaces this file.
#include <cstdio>

#include "app/Command.h"

namespace parksim::app {

CommandRunner setupRunCommand(CLI::App&) {
  return [] {
    std::fprintf(stderr, "parksim run: not available in this build yet\n");
    return 2;
  };
}

}  // namespace parksim::app
