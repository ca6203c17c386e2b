#include "parksim/renders/film/FrameRecorder.h"

#include <algorithm>
#include <cstddef>
#include <string>

#include "parksim/core/io/Error.h"

// How a recording spends its memory budget on frames (FrameDef::frame_memory_bytes), and the
// most memory it holds that grows with its frame (docs/limits.md).

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

std::size_t filmPeakBytes(const FrameDef& def) {
  const std::size_t view_pixels = static_cast<std::size_t>(std::max(def.width_px, 0)) *
                                  static_cast<std::size_t>(std::max(def.height_px, 0));
  // The drawing framebuffer and the top view's backdrop: colour (RGBA8) and depth (4 bytes in
  // Mesa) each, per sample; with samples, a resolved colour besides. The samples asked for are
  // counted (the GL may give fewer).
  const auto samples = static_cast<std::size_t>(std::max(def.msaa_samples, 1));
  const std::size_t framebuffers = view_pixels * (samples == 1 ? 16 : 16 * samples + 4);
  const FilmBuffers frames = filmBuffers(def);
  const std::size_t rgb = frames.frame_bytes / 4 * 3;  // a frame as the PNG holds it
  std::size_t encoder = 0;
  if (def.png_compression == PngCompression::kStored) encoder = rgb;
  if (def.png_compression == PngCompression::kSmall) encoder = 3 * rgb;
  return framebuffers + frames.bytes() +
         static_cast<std::size_t>(std::max(def.encode_threads, 1)) * encoder +
         kMaxQueuedSampleBytes;
}

void checkFilmMemory(const FrameDef& def) {
  const std::size_t peak = filmPeakBytes(def);
  if (peak <= kFilmMemoryBoundBytes) return;
  throw Error("frames: size " + std::to_string(def.width_px) + "x" + std::to_string(def.height_px) +
              ", view " + toString(def.view) + ", png_compression " +
              toString(def.png_compression) + ", msaa_samples " + std::to_string(def.msaa_samples) +
              ", encode_threads " + std::to_string(def.encode_threads) + " would hold " +
              std::to_string(peak) + " bytes, more than the bound of " +
              std::to_string(kFilmMemoryBoundBytes) + " (docs/limits.md)");
}

}  // namespace parksim
