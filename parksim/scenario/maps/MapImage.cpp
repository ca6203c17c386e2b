#include "parksim/scenario/maps/MapImage.h"

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include <stb/stb_image.h>  // implementation linked from libstb

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/Text.h"
#include "parksim/scenario/maps/MapLimits.h"

namespace parksim {

namespace {

// Bytes read first for the header: a PNG's size is in its first 24, a PGM's after its magic
// number and any comments.
constexpr std::size_t kImageHeadBytes = 65536;

[[noreturn]] void imageFail(const std::string& path, const std::string& what, int line = 0) {
  throw Error(
      escapeText(path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what));
}

void checkMapSize(const std::string& path, std::int64_t width, std::int64_t height) {
  if (width < 1 || height < 1) {
    imageFail(path, "the image is " + std::to_string(width) + " x " + std::to_string(height) +
                        " pixels; a map needs at least one");
  }
  if (width > kMaxMapSideCells || height > kMaxMapSideCells || width * height > kMaxMapCells) {
    imageFail(path, "the image is " + std::to_string(width) + " x " + std::to_string(height) +
                        " pixels, more than the limit of " + std::to_string(kMaxMapSideCells) +
                        " a side and " + std::to_string(kMaxMapCells) +
                        " in all for a map (docs/limits.md)");
  }
}

// The header and samples of a PGM file, read token by token; lines are counted for messages.
class PgmReader {
 public:
  PgmReader(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

  // The header's width and height when `bytes` (a file's first bytes) hold them whole; nothing
  // when they end inside it (the full read then says what is wrong).
  std::optional<std::pair<std::int64_t, std::int64_t>> size() {
    pos_ = 2;
    std::int64_t dims[2] = {0, 0};
    for (std::int64_t& d : dims) {
      skipSpace(true);
      if (pos_ >= bytes_.size()) return std::nullopt;
      d = number(&d == dims ? "width" : "height");
      if (pos_ >= bytes_.size()) return std::nullopt;  // the number may go on
    }
    return std::pair{dims[0], dims[1]};
  }

  MapImage read() {
    const bool plain = bytes_[1] == '2';
    pos_ = 2;
    const std::int64_t width = headerNumber("width");
    const std::int64_t height = headerNumber("height");
    checkMapSize(path_, width, height);
    const std::int64_t max_value = headerNumber("maximum value");
    if (max_value < 1 || max_value > 65535) {
      imageFail(path_, "PGM maximum value " + std::to_string(max_value) + " is not in [1, 65535]",
                line_);
    }
    MapImage image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    const auto pixels = static_cast<std::size_t>(width * height);
    image.shade.resize(pixels);
    const auto scale = static_cast<float>(1.0 / static_cast<double>(max_value));
    if (plain) {
      for (std::size_t k = 0; k < pixels; ++k) {
        skipSpace(false);
        if (pos_ >= bytes_.size()) {
          imageFail(path_,
                    "truncated: the header says " + std::to_string(width) + " x " +
                        std::to_string(height) + " pixels, the file ends after " +
                        std::to_string(k),
                    line_);
        }
        const std::int64_t v = number("pixel value");
        if (v > max_value) {
          imageFail(path_,
                    "pixel value " + std::to_string(v) + " is above the maximum value " +
                        std::to_string(max_value),
                    line_);
        }
        image.shade[k] = static_cast<float>(v) * scale;
      }
      skipSpace(false);
      if (pos_ < bytes_.size()) {
        imageFail(path_,
                  "size mismatch: more values than the header's " + std::to_string(width) + " x " +
                      std::to_string(height) + " pixels",
                  line_);
      }
      return image;
    }
    // Binary: exactly one whitespace byte after the maximum value, then the raster.
    if (pos_ >= bytes_.size() || !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
      imageFail(path_, "truncated: no raster after the PGM header");
    }
    ++pos_;
    const std::size_t bytes_per = max_value > 255 ? 2 : 1;
    const std::size_t expected = pixels * bytes_per;
    const std::size_t held = bytes_.size() - pos_;
    if (held != expected) {
      imageFail(path_, std::string(held < expected ? "truncated" : "size mismatch") +
                           ": the header says " + std::to_string(width) + " x " +
                           std::to_string(height) + " pixels (" + std::to_string(expected) +
                           " bytes), the file holds " + std::to_string(held) +
                           " bytes after the header");
    }
    const auto* raster = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    for (std::size_t k = 0; k < pixels; ++k) {
      const unsigned v =
          bytes_per == 2 ? (unsigned(raster[2 * k]) << 8) | raster[2 * k + 1] : unsigned(raster[k]);
      if (v > static_cast<unsigned>(max_value)) {
        imageFail(path_, "pixel " + std::to_string(k) + " has value " + std::to_string(v) +
                             ", above the maximum value " + std::to_string(max_value));
      }
      image.shade[k] = static_cast<float>(v) * scale;
    }
    return image;
  }

 private:
  // Whitespace, and in the header comments from '#' to the end of the line.
  void skipSpace(bool comments) {
    while (pos_ < bytes_.size()) {
      const char c = bytes_[pos_];
      if (c == '\n') ++line_;
      if (comments && c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
        continue;
      }
      if (!std::isspace(static_cast<unsigned char>(c))) return;
      ++pos_;
    }
  }

  std::int64_t number(const char* what) {
    std::int64_t v = 0;
    std::size_t digits = 0;
    while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_]))) {
      if (v > 1'000'000'000'000LL) imageFail(path_, std::string(what) + ": too large", line_);
      v = 10 * v + (bytes_[pos_] - '0');
      ++pos_;
      ++digits;
    }
    if (digits == 0) {
      imageFail(path_,
                pos_ < bytes_.size()
                    ? std::string(what) + ": expected a whole number, got '" + bytes_[pos_] + "'"
                    : std::string("truncated: the file ends before the ") + what,
                line_);
    }
    return v;
  }

  std::int64_t headerNumber(const char* what) {
    skipSpace(true);
    return number(what);
  }

  const std::string& path_;
  std::string_view bytes_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

MapImage readPng(const std::string& path, const std::string& bytes) {
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());
  int w = 0;
  int h = 0;
  int channels = 0;
  if (!stbi_info_from_memory(data, size, &w, &h, &channels)) {
    imageFail(path, std::string("cannot read the PNG: ") + stbi_failure_reason());
  }
  checkMapSize(path, w, h);
  const bool sixteen = stbi_is_16_bit_from_memory(data, size) != 0;
  std::unique_ptr<void, StbFree> pixels(
      sixteen ? static_cast<void*>(stbi_load_16_from_memory(data, size, &w, &h, &channels, 0))
              : static_cast<void*>(stbi_load_from_memory(data, size, &w, &h, &channels, 0)));
  if (!pixels) imageFail(path, std::string("cannot decode the PNG: ") + stbi_failure_reason());
  MapImage image;
  image.width = w;
  image.height = h;
  image.has_alpha = channels == 2 || channels == 4;
  const int colours = image.has_alpha ? channels - 1 : channels;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  image.shade.resize(n);
  if (image.has_alpha) image.opacity.resize(n);
  const double full = sixteen ? 65535.0 : 255.0;
  const auto sample = [&](std::size_t i) {
    return sixteen ? static_cast<double>(static_cast<const std::uint16_t*>(pixels.get())[i])
                   : static_cast<double>(static_cast<const stbi_uc*>(pixels.get())[i]);
  };
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t base = k * static_cast<std::size_t>(channels);
    double sum = 0.0;
    for (int c = 0; c < colours; ++c) sum += sample(base + static_cast<std::size_t>(c));
    image.shade[k] = static_cast<float>(sum / (colours * full));
    if (image.has_alpha) {
      image.opacity[k] =
          static_cast<float>(sample(base + static_cast<std::size_t>(channels - 1)) / full);
    }
  }
  return image;
}

}  // namespace

MapImage readMapImage(const std::string& path) {
  static constexpr std::string_view kPngSignature("\x89PNG\r\n\x1a\n", 8);
  const auto is_pgm = [](std::string_view b) {
    return b.size() >= 2 && b[0] == 'P' && (b[1] == '2' || b[1] == '5');
  };
  {
    // The header alone decides the size limits: checked before the pixels are read.
    const std::string head = readInputFileHead(path, kImageHeadBytes, "map image");
    if (is_pgm(head)) {
      if (const auto wh = PgmReader(path, head).size()) checkMapSize(path, wh->first, wh->second);
    } else if (std::string_view(head).substr(0, 8) == kPngSignature && head.size() >= 24 &&
               std::string_view(head).substr(12, 4) == "IHDR") {
      // The first chunk, IHDR: width and height big-endian at bytes 16 and 20 (stb's own
      // reader refuses a size beyond 2^30 pixels with a message that does not name ours).
      const auto be32 = [&](std::size_t at) {
        std::int64_t v = 0;
        for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(head[at + k]);
        return v;
      };
      checkMapSize(path, be32(16), be32(20));
    }
  }
  const std::string bytes = readInputFile(path, kMaxMapFileBytes, "map image");
  if (is_pgm(bytes)) return PgmReader(path, bytes).read();
  if (std::string_view(bytes).substr(0, 8) == kPngSignature) return readPng(path, bytes);
  imageFail(path,
            "not a PGM (P2 or P5) or PNG image; a map server image must be one of those "
            "(convert it, e.g. with ImageMagick: convert map.jpg map.png)");
}

}  // namespace parksim
