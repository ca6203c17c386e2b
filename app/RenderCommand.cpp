// Placeholder until the render command lands; its owner replaces this file.
#include <cstdio>

#include "app/Command.h"

namespace parksim::app {

CommandRunner setupRenderCommand(CLI::App&) {
  return [] {
    std::fprintf(stderr, "parksim render: not available in this build yet\n");
    return 2;
  };
}

}  // namespace parksim::app
