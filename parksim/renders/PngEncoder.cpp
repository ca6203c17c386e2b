// This file holds its own copy of stb_image_write with the deflate routed to zlib; the copy in
// PngEncoderStb.cpp keeps stb's. Both are static, so they coexist with each other and libstb.
#include "parksim/renders/PngEncoder.h"

#include <zlib.h>

#include <cstdlib>
#include <cstring>
#include <string_view>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"

namespace {

// stb frees the result with STBIW_FREE (free), so it is allocated with malloc. `quality` is
// stb's compression level, set to 1 below.
unsigned char* zlibCompress(unsigned char* data, int data_len, int* out_len, int quality) {
  uLongf size = compressBound(static_cast<uLong>(data_len));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (out == nullptr) return nullptr;
  if (compress2(out, &size, data, static_cast<uLong>(data_len), quality) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_len = static_cast<int>(size);
  return out;
}

}  // namespace

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#define STBIW_ZLIB_COMPRESS zlibCompress
#include <stb/stb_image_write.h>

#include <stb/stb_image.h>  // implementation linked from libstb

namespace parksim {

namespace {

// stb reads its settings from file-scope variables; this copy's are set once, before any
// encoding, and never changed again, so concurrent encoders only read them.
void configureStb() {
  static const bool configured = [] {
    stbi_write_png_compression_level = 1;
    stbi_write_force_png_filter = 0;
    return true;
  }();
  (void)configured;
}

}  // namespace

std::vector<unsigned char> encodePng(const RgbImage& image, PngDeflate deflate) {
  if (deflate == PngDeflate::kStbDefault) return detail::encodePngStbDefault(image);
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw Error("PNG: image has no pixels or a wrong buffer size");
  }
  configureStb();
  int len = 0;
  unsigned char* png = stbi_write_png_to_mem(image.pixels.data(), image.width * 3, image.width,
                                             image.height, 3, &len);
  if (png == nullptr) throw Error("PNG: encoding failed (out of memory?)");
  std::vector<unsigned char> bytes(png, png + len);
  STBIW_FREE(png);
  return bytes;
}

void writePng(const std::string& path, const RgbImage& image, PngDeflate deflate) {
  const std::vector<unsigned char> bytes = encodePng(image, deflate);
  writeFileAtomically(path,
                      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

RgbImage readPng(const std::string& path) {
  int w = 0;
  int h = 0;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (data == nullptr) {
    const char* reason = stbi_failure_reason();
    throw Error(path + ": cannot read image: " + (reason != nullptr ? reason : "unknown"));
  }
  RgbImage image(w, h);
  std::memcpy(image.pixels.data(), data, image.pixels.size());
  stbi_image_free(data);
  return image;
}

}  // namespace parksim
