#pragma once
// PNG files through stb_image_write. stb's own deflate is slow (~11 ms for a 640x480 frame), so
// by default its compression is routed to zlib's compress2 at level 1 with PNG filter 0 (none),
// about ten times faster for a few percent larger files. Both are kept so the benchmark can put
// them side by side. Encoding is thread-safe.

#include <string>
#include <vector>

#include "parksim/renders/Image.h"

namespace parksim {

enum class PngDeflate {
  kZlibFast,    ///< zlib compress2 level 1, filter 0: fast; the default
  kStbDefault,  ///< stb's built-in deflate, level 8, best filter per row: small and slow
};

/// PNG file bytes of `image` (8-bit RGB). Throws Error when encoding fails.
std::vector<unsigned char> encodePng(const RgbImage& image,
                                     PngDeflate deflate = PngDeflate::kZlibFast);

/// Writes `image` to `path` as PNG, atomically (the file appears complete or not at all).
/// Throws Error naming the path.
void writePng(const std::string& path, const RgbImage& image,
              PngDeflate deflate = PngDeflate::kZlibFast);

/// Reads a PNG (or any image stb_image reads) as 8-bit RGB. Throws Error naming the path.
RgbImage readPng(const std::string& path);

namespace detail {
/// stb's built-in deflate (PngEncoderStb.cpp, a separate copy of stb_image_write).
std::vector<unsigned char> encodePngStbDefault(const RgbImage& image);
}  // namespace detail

}  // namespace parksim
