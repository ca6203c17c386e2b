// Placeholder until the bench command lands; its owner replaces this file.
#include <cstdio>

#include "app/Command.h"

namespace parksim::app {

CommandRunner setupBenchCommand(CLI::App&) {
  return [] {
    std::fprintf(stderr, "parksim bench: not available in this build yet\n");
    return 2;
  };
}

}  // namespace parksim::app
