#include "parksim/renders/film/FrameRecorder.h"

#include <algorithm>
#include <cstddef>

// How a recording spends its memory budget on frames (FrameDef::frame_memory_bytes).

namespace parksim {

FilmBuffers filmBuffers(const FrameDef& def) {
  FilmBuffers b;
  const int width = def.view == FrameView::kBoth ? 2 * def.width_px : def.width_px;
  b.frame_bytes = static_cast<std::size_t>(std::max(width, 0)) *
                  static_cast<std::size_t>(std::max(def.height_px, 0)) * 4;
  const std::size_t frame = std::max<std::size_t>(b.frame_bytes, 1);
  const std::size_t budget = def.frame_memory_bytes;
  const int threads = std::max(def.encode_threads, 1);
  // Keeping the last frame saves the encoders most of their work on a film (and the top view
  // most of its read-back): it comes before frames rendered ahead, which only smooth the flow.
  if (keepsLastImage(def.png_compression) &&
      (static_cast<std::size_t>(threads) + 1) <= budget / frame) {
    b.kept = threads;
  }
  const std::size_t room = (budget - static_cast<std::size_t>(b.kept) * b.frame_bytes) / frame;
  const int most = std::max(def.queue_depth, 1) + threads;
  b.images = static_cast<int>(std::clamp<std::size_t>(room, 1, static_cast<std::size_t>(most)));
  return b;
}

}  // namespace parksim
