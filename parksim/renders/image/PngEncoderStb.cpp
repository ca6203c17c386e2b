// stb_image_write with its own deflate and default settings (level 8, best filter per row):
// the baseline the zlib route in PngEncoder.cpp is measured against.
#include "parksim/renders/image/PngEncoder.h"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

#include "parksim/core/io/Error.h"

namespace parksim::detail {

std::vector<unsigned char> encodePngStbDefault(const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw Error("PNG: image has no pixels or a wrong buffer size");
  }
  int len = 0;
  unsigned char* png = stbi_write_png_to_mem(image.pixels.data(), image.width * 3, image.width,
                                             image.height, 3, &len);
  if (png == nullptr) throw Error("PNG: encoding failed (out of memory?)");
  std::vector<unsigned char> bytes(png, png + len);
  STBIW_FREE(png);
  return bytes;
}

}  // namespace parksim::detail
