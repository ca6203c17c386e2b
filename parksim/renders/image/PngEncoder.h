#pragma once
// PNG files of 8-bit RGB images. Frames (and by default every encodePng) are written with PNG
// filter 0 (none) and zlib level 1, ten times faster than stb_image_write's own deflate for
// files 15 % larger, in bands of rows that a PngEncoder copies from the last image it encoded
// where they did not change; for speed over size, a run-length deflate (also in bands) or no
// compression at all (PngCompression, docs/rendering.md). stb's deflate (level 8, best filter
// per row: small and slow) is kept for the figures and so the benchmark can put them side by
// side. Encoding is thread-safe; a PngEncoder keeps its zlib state and buffers for the next
// image.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "parksim/renders/image/Image.h"

namespace parksim {

/// How PNGs are compressed: frames (FrameDef::png_compression) and figures (kSmall).
enum class PngCompression {
  /// zlib level 1: fast and small (~25 kB a 640x480 frame), chosen by measurement. Bands of 32
  /// rows are compressed each on its own, so a PngEncoder copies those of a film's frame that
  /// the last frame already had.
  kDefault,
  /// Speed over size: repeats of the pixel before and the row above only, fixed Huffman codes
  /// (RunLengthDeflate.h), in bands as kDefault. About 60 % of kDefault's CPU on a film's
  /// frames, a quarter on images that share nothing; files about kDefault's size on films
  /// (0.86-1.04x), up to twice it on busy images.
  kFast,
  /// No compression: 3 bytes a pixel (0.92 MB a 640x480 frame). Encoding costs only a copy,
  /// but on a disk, writing such files costs more than compressing them (docs/rendering.md).
  kStored,
  /// stb_image_write's own deflate (level 8) and the best PNG filter per row: the smallest
  /// files, ~10x slower to encode than kDefault (~40x on films, whose bands kDefault copies).
  /// For figures, written once each.
  kSmall,
};

/// Whether a PngEncoder keeps the last image it encoded (kDefault and kFast, which compress in
/// bands and copy the unchanged ones), so that it can be told which rows changed.
bool keepsLastImage(PngCompression compression);

/// "default", "fast", "stored", "small".
const char* toString(PngCompression compression);
/// Parses what toString gives; throws Error naming the four otherwise.
PngCompression pngCompressionFromString(const std::string& name);

/// Encodes PNGs (8-bit RGB; filter 0 but for kSmall), reusing its zlib state and buffers from one
/// image to the next: for a thread that writes many frames. kDefault and kFast also keep the last
/// image (as it came, RGB or RGBA) and its compressed bands, and copy each band that is unchanged
/// instead of compressing it. The bytes depend only on the image and the compression, never on
/// what was encoded before. Besides that last image, an encoder holds its output (twice, the last
/// one and the next, when it keeps the last image) and a band of rows; kSmall also an RGB copy and
/// stb's whole filtered image.
class PngEncoder {
 public:
  /// `keep_last_image` false: kDefault and kFast keep no last image and compress every band (the
  /// same bytes; for images too large to hold twice), and encode with changed rows throws.
  explicit PngEncoder(PngCompression compression = PngCompression::kDefault,
                      bool keep_last_image = true);
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  /// The PNG file bytes of `image`, valid until the next call. Throws Error when the image has
  /// no pixels or a wrong buffer size.
  std::span<const unsigned char> encode(const RgbImage& image);
  /// The same for an image read back with its alpha, which the PNG drops: a film's frames come
  /// so, and only the bands that changed are converted (the bytes are encode(image.rgb())'s).
  std::span<const unsigned char> encode(const RgbaImage& image);
  /// The same for the next frame of a film, of which only rows `changed` (sorted and apart,
  /// Renderer::renderChanges) are read: the others are the last image's. Throws Error when
  /// there is no last image of this size (or encoding it failed), when it keeps none (kStored,
  /// kSmall, keep_last_image false), and for rows out of order or outside the image. The bytes are
  /// those of encode() of the whole frame.
  std::span<const unsigned char> encode(const RgbaImage& image, std::span<const RowSpan> changed);

  /// Whether it keeps the last image: kDefault or kFast, and keep_last_image.
  bool keepsLast() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// PNG file bytes of `image` (8-bit RGB) compressed as `compression` says. Throws Error when
/// encoding fails.
std::vector<unsigned char> encodePng(const RgbImage& image,
                                     PngCompression compression = PngCompression::kDefault);

/// Writes `image` to `path` as PNG, atomically (the file appears complete or not at all).
/// Throws Error naming the path.
void writePng(const std::string& path, const RgbImage& image,
              PngCompression compression = PngCompression::kDefault);

/// Reads a PNG (or any image stb_image reads) as 8-bit RGB. Throws Error naming the path.
RgbImage readPng(const std::string& path);

namespace detail {
/// stb's built-in deflate (PngEncoderStb.cpp, a separate copy of stb_image_write).
std::vector<unsigned char> encodePngStbDefault(const RgbImage& image);
}  // namespace detail

}  // namespace parksim
