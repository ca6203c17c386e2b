#include "parksim/renders/image/PngEncoder.h"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <stb/stb_image.h>  // implementation linked from libstb

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/renders/image/RunLengthDeflate.h"

namespace parksim {

namespace {

void put32(unsigned char* p, std::uint32_t v) {
  p[0] = static_cast<unsigned char>(v >> 24);
  p[1] = static_cast<unsigned char>(v >> 16);
  p[2] = static_cast<unsigned char>(v >> 8);
  p[3] = static_cast<unsigned char>(v);
}

// One IDAT chunk holds the image: its length field and zlib's counters (uInt) are 32 bits.
constexpr std::size_t kMaxPixelBytes = std::size_t{1} << 30;

// An image as given to encode: RGB or RGBA rows.
struct Pixels {
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;  // bytes
  int width = 0;
  int height = 0;
  int channels = 3;
  // Set: only these rows are read, the others are the last image's (PngEncoder::encode).
  std::optional<std::span<const RowSpan>> changed;
};

void checkImage(const Pixels& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.size != static_cast<std::size_t>(image.width) * image.height * image.channels) {
    throw Error("PNG: image has no pixels or a wrong buffer size");
  }
  if (static_cast<std::size_t>(image.width) * image.height * 3 > kMaxPixelBytes) {
    throw Error("PNG: " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " is more than 1 GiB of pixels");
  }
}

// `adler` updated with a row as the PNG holds it: filter byte 0 (none), then its pixels.
// libdeflate's Adler-32 (vectorised; 0.013 ms a 640x480 frame where zlib's byte loop takes
// 0.23 ms and the SSE2 loop parksim had 0.060 ms: docs/rendering.md).
std::uint32_t filteredRowAdler(std::uint32_t adler, const unsigned char* row,
                               std::size_t row_bytes) {
  static constexpr unsigned char kFilterNone = 0;
  return libdeflate_adler32(libdeflate_adler32(adler, &kFilterNone, 1), row, row_bytes);
}

constexpr unsigned char kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
constexpr std::size_t kIdatStart = 8 + 12 + 13 + 8;  // signature, IHDR chunk, IDAT length and tag
// After the deflate data: its Adler-32, the IDAT chunk's CRC and the IEND chunk.
constexpr std::size_t kTrailerBytes = 4 + 4 + 12;

constexpr int kZlibLevel = 1;  // PngCompression::kDefault
// kDefault and kFast compress bands of this many rows, each on its own (encodeBands). Smaller
// bands leave more of a film's frame to copy from the last one; each band costs its matches
// into the band before (kDefault), a block header and a flush: ~2 % of a film frame's bytes at
// 32 rows, 5 % at 16.
constexpr int kBandRows = 32;
// The zlib stream header (RFC 1950) zlib writes at level 1: deflate with a 32 kB window, level
// field 0 ("fastest"; advisory, readers ignore it), check bits.
constexpr unsigned char kZlibHeader[2] = {0x78, 0x01};

}  // namespace

// The PNG is built in place in `out`: signature, IHDR, one IDAT chunk holding the zlib stream
// (header, raw deflate, Adler-32), IEND. The filtered image (each row a 0 byte, filter "none",
// then its pixels) is never assembled: rows go to deflate, or into stored blocks, as they are,
// an RGBA image's converted a band (or a row) at a time. Nothing the size of the image is held
// but the last image (kDefault and kFast, when kept) and the output.
struct PngEncoder::Impl {
  // kDefault and kFast: what is kept of a band of the last image to copy it into the next.
  struct Band {
    std::size_t offset = 0;   // of its compressed bytes in the last output
    std::size_t length = 0;   // compressed bytes
    std::uint32_t adler = 1;  // of its filtered rows
    bool changed = true;      // this image's rows differ from the last image's
  };

  PngCompression compression = PngCompression::kDefault;
  bool keep_last = true;  // kDefault and kFast: keep the last image, copy its unchanged bands
  z_stream zs{};
  bool deflating = false;  // zs initialized (kDefault)
  // Two outputs, used in turn: the last one stays readable while the next is made. They only
  // grow (doubling, band by band as the PNG needs), and out_size says how much is the PNG:
  // growing a vector zeroes its new bytes, which costs a frame nothing once they fit.
  std::vector<unsigned char> outs[2];
  std::size_t out_size[2] = {0, 0};
  int current = 0;
  // kDefault and kFast with keep_last: the last image encoded, as it came (RGB or RGBA), to
  // compare the next one's bands with and to take the rows a changed-rows call does not give.
  // last_width 0: none, or it failed.
  std::vector<std::uint8_t> last;
  int last_width = 0;
  int last_height = 0;
  int last_channels = 0;
  RgbImage rgb;                           // kSmall: an RGBA image as RGB (stb takes it whole)
  std::vector<std::uint8_t> rows_rgb;     // an RGBA image's rows of one band (or row) as RGB
  std::vector<Band> band_cache;           // the last image's bands
  std::vector<unsigned char> filtered;    // kFast: a band's rows and the row above, filtered
  std::vector<unsigned char> band_bytes;  // kFast: one band's deflate blocks
  std::uint32_t adler = 1;                // of the filtered rows

  std::span<const unsigned char> encode(const Pixels& image);
  void begin(const Pixels& image);
  // Makes out() hold at least `bytes` of PNG data, and the trailer after them.
  void reserveOut(std::size_t bytes);
  const std::uint8_t* rgbRows(const std::uint8_t* source, const Pixels& image, int y0, int y1);
  template <class CompressBand>
  std::size_t encodeBands(const Pixels& image, bool matches_row_above, std::size_t band_bound,
                          CompressBand compress);
  std::size_t deflateRows(const Pixels& image, std::size_t band_bound);
  std::size_t storeRows(const Pixels& image);
  std::size_t runLengthRows(const Pixels& image, std::size_t band_bound);
  void checksumRow(const unsigned char* row, std::size_t row_bytes) {
    adler = filteredRowAdler(adler, row, row_bytes);
  }
  void finish(std::size_t deflated);
  std::vector<unsigned char>& out() { return outs[current]; }
};

void PngEncoder::Impl::reserveOut(std::size_t bytes) {
  const std::size_t need = bytes + kTrailerBytes;
  if (out().size() < need) out().resize(std::max(need, 2 * out().size()));
}

void PngEncoder::Impl::begin(const Pixels& image) {
  reserveOut(kIdatStart + 2);
  unsigned char* o = out().data();
  std::memcpy(o, kSignature, 8);
  put32(o + 8, 13);
  std::memcpy(o + 12, "IHDR", 4);
  put32(o + 16, static_cast<std::uint32_t>(image.width));
  put32(o + 20, static_cast<std::uint32_t>(image.height));
  // 8 bits a channel, RGB, deflate, filter method 0, no interlace.
  const unsigned char format[5] = {8, 2, 0, 0, 0};
  std::memcpy(o + 24, format, 5);
  put32(o + 29, static_cast<std::uint32_t>(crc32(0, o + 12, 17)));
  std::memcpy(o + 37, "IDAT", 4);
  o[kIdatStart] = kZlibHeader[0];
  o[kIdatStart + 1] = kZlibHeader[1];
}

// Rows [y0, y1) of `source` (laid out as `image`) as RGB, one after the other: the rows
// themselves when the image is RGB, else converted into rows_rgb.
const std::uint8_t* PngEncoder::Impl::rgbRows(const std::uint8_t* source, const Pixels& image,
                                              int y0, int y1) {
  const std::size_t width = static_cast<std::size_t>(image.width);
  const std::size_t first = static_cast<std::size_t>(y0) * width * image.channels;
  if (image.channels == 3) return source + first;
  const std::size_t pixels = static_cast<std::size_t>(y1 - y0) * width;
  if (rows_rgb.size() < pixels * 3) rows_rgb.resize(pixels * 3);
  rgbaToRgb(source + first, rows_rgb.data(), pixels);
  return rows_rgb.data();
}

// kDefault and kFast: the image in bands of kBandRows rows, each compressed on its own and ended
// on a byte boundary (a sync flush), so its bytes depend on its rows alone and, where its
// matches reach the row above (kFast), on the row before it. A film's frames share most rows
// (the lot stays, the robot moves): with keep_last, a band that the last image had too is
// copied from the last output with its Adler-32 instead of compressed, and the bytes are the
// same as compressing it. An image is compared and kept as it came; an RGBA image's bands are
// converted to RGB only where they are compressed. `compress(y0, y1, rows, above, o, end)`
// writes rows [y0, y1) (RGB at `rows`; `above`: the row before them, or null) at `o` (room up
// to `end`, at least band_bound) and returns the bytes written.
template <class CompressBand>
std::size_t PngEncoder::Impl::encodeBands(const Pixels& image, bool matches_row_above,
                                          std::size_t band_bound, CompressBand compress) {
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  const std::size_t in_row_bytes = static_cast<std::size_t>(image.width) * image.channels;
  const auto bands = static_cast<std::size_t>((image.height + kBandRows - 1) / kBandRows);
  const bool same_size = keep_last && last_width == image.width && last_height == image.height &&
                         last_channels == image.channels;
  last_width = last_height = 0;  // until this image is done
  if (keep_last && !same_size) last.assign(image.size, 0);
  // Rows [y0, y1) as they came: compared with the last image's and, where they differ, kept.
  // True when they differ (always, with no last image).
  const auto take = [&](int y0, int y1) {
    if (!keep_last) return true;
    const std::size_t first = static_cast<std::size_t>(y0) * in_row_bytes;
    const std::size_t bytes = static_cast<std::size_t>(y1 - y0) * in_row_bytes;
    if (same_size && std::memcmp(image.data + first, last.data() + first, bytes) == 0) {
      return false;
    }
    std::memcpy(last.data() + first, image.data + first, bytes);
    return true;
  };
  band_cache.resize(bands);
  std::size_t span = 0;  // the first changed span that may reach this band
  for (std::size_t b = 0; b < bands; ++b) {
    const int y0 = static_cast<int>(b) * kBandRows;
    const int y1 = std::min(image.height, y0 + kBandRows);
    Band& band = band_cache[b];
    if (!image.changed) {
      band.changed = take(y0, y1);
      continue;
    }
    band.changed = false;
    const std::span<const RowSpan> rows = *image.changed;
    while (span < rows.size() && rows[span].end <= y0) ++span;
    for (std::size_t k = span; k < rows.size() && rows[k].begin < y1; ++k) {
      band.changed |= take(std::max(y0, rows[k].begin), std::min(y1, rows[k].end));
    }
  }
  // The image's rows: all of them kept by now, or all given.
  const std::uint8_t* const source = keep_last ? last.data() : image.data;
  const std::vector<unsigned char>& last_out = outs[1 - current];
  const std::size_t start = kIdatStart + 2;
  std::size_t at = start;
  for (std::size_t b = 0; b < bands; ++b) {
    const int y0 = static_cast<int>(b) * kBandRows;
    const int y1 = std::min(image.height, y0 + kBandRows);
    Band& band = band_cache[b];
    if (band.changed || (matches_row_above && b > 0 && band_cache[b - 1].changed)) {
      const int from = matches_row_above && y0 > 0 ? y0 - 1 : y0;
      const std::uint8_t* const above = rgbRows(source, image, from, y1);
      const std::uint8_t* const rows = above + static_cast<std::size_t>(y0 - from) * row_bytes;
      band.adler = 1;
      for (int y = y0; y < y1; ++y) {
        band.adler = filteredRowAdler(band.adler, rows + (y - y0) * row_bytes, row_bytes);
      }
      reserveOut(at + band_bound);
      band.length = compress(y0, y1, rows, from < y0 ? above : nullptr, out().data() + at,
                             out().data() + out().size() - kTrailerBytes);
    } else {
      reserveOut(at + band.length);
      std::memcpy(out().data() + at, last_out.data() + band.offset, band.length);
    }
    band.offset = at;
    at += band.length;
    adler =
        adler32_combine(adler, band.adler,
                        static_cast<z_off_t>(static_cast<std::size_t>(y1 - y0) * (row_bytes + 1)));
  }
  // The last block: empty, fixed codes, final.
  reserveOut(at + 2);
  out()[at] = 0x03;
  out()[at + 1] = 0x00;
  at += 2;
  if (keep_last) {
    last_width = image.width;
    last_height = image.height;
    last_channels = image.channels;
  }
  return at - start;
}

// kDefault: each band a raw deflate stream of zlib level 1 (the state reset before it).
std::size_t PngEncoder::Impl::deflateRows(const Pixels& image, std::size_t band_bound) {
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  return encodeBands(image, false, band_bound,
                     [&](int y0, int y1, const std::uint8_t* rows, const std::uint8_t*,
                         unsigned char* o, const unsigned char* end) {
                       if (deflateReset(&zs) != Z_OK) {
                         throw Error("PNG: zlib cannot reset its state");
                       }
                       zs.next_out = o;
                       zs.avail_out = static_cast<uInt>(end - o);
                       unsigned char filter = 0;
                       auto feed = [this](const unsigned char* data, std::size_t n, int flush) {
                         zs.next_in = const_cast<unsigned char*>(data);  // zlib reads only
                         zs.avail_in = static_cast<uInt>(n);
                         // The output has room for the band's bound: all input is taken.
                         if (deflate(&zs, flush) != Z_OK || zs.avail_in != 0) {
                           throw Error("PNG: zlib failed to compress");
                         }
                       };
                       for (int y = y0; y < y1; ++y) {
                         feed(&filter, 1, Z_NO_FLUSH);
                         feed(rows + (y - y0) * row_bytes, row_bytes,
                              y + 1 == y1 ? Z_SYNC_FLUSH : Z_NO_FLUSH);
                       }
                       // A full output would leave part of the flush inside zlib (it returns
                       // Z_OK then too).
                       if (zs.avail_out == 0) throw Error("PNG: zlib outgrew its bound");
                       return static_cast<std::size_t>(zs.next_out - o);
                     });
}

// kStored: blocks of at most 65535 bytes (RFC 1951 3.2.4), copied straight from the rows (an
// RGBA image's converted a row at a time).
std::size_t PngEncoder::Impl::storeRows(const Pixels& image) {
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  const std::size_t total = (row_bytes + 1) * static_cast<std::size_t>(image.height);
  reserveOut(kIdatStart + 2 + total + 5 * (total / 65535 + 1));
  unsigned char* o = out().data() + kIdatStart + 2;
  unsigned char* const start = o;
  std::size_t row = 0;
  const std::uint8_t* rgb_row = nullptr;  // the current row's pixels
  std::size_t in_row = 0;                 // position in the current row, its filter byte counted
  for (std::size_t done = 0; done < total;) {
    const std::size_t block = std::min<std::size_t>(65535, total - done);
    *o++ = done + block == total ? 1 : 0;  // BFINAL on the last, BTYPE 00
    o[0] = static_cast<unsigned char>(block);
    o[1] = static_cast<unsigned char>(block >> 8);
    o[2] = static_cast<unsigned char>(~block);
    o[3] = static_cast<unsigned char>(~block >> 8);
    o += 4;
    for (std::size_t left = block; left > 0;) {
      if (in_row == 0) {
        *o++ = 0;  // filter: none
        rgb_row = rgbRows(image.data, image, static_cast<int>(row), static_cast<int>(row) + 1);
        ++in_row;
        --left;
        continue;
      }
      const std::size_t n = std::min(left, row_bytes + 1 - in_row);
      std::memcpy(o, rgb_row + (in_row - 1), n);
      o += n;
      left -= n;
      in_row += n;
      if (in_row == row_bytes + 1) {
        checksumRow(rgb_row, row_bytes);
        in_row = 0;
        ++row;
      }
    }
    done += block;
  }
  return static_cast<std::size_t>(o - start);
}

// kFast: each band a block of the run-length deflate, which matches into the row above it: the
// band is filtered with that row before it.
std::size_t PngEncoder::Impl::runLengthRows(const Pixels& image, std::size_t band_bound) {
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  const std::size_t stride = row_bytes + 1;
  return encodeBands(
      image, true, band_bound,
      [&](int y0, int y1, const std::uint8_t* rows, const std::uint8_t* above, unsigned char* o,
          const unsigned char* end) {
        const std::size_t first = above != nullptr ? 1 : 0;  // rows in `filtered` before y0
        const std::size_t count = static_cast<std::size_t>(y1 - y0);
        filtered.resize(stride * (first + count));
        for (std::size_t i = 0; i < first + count; ++i) {
          unsigned char* dst = filtered.data() + i * stride;
          dst[0] = 0;
          std::memcpy(dst + 1, i < first ? above : rows + (i - first) * row_bytes, row_bytes);
        }
        band_bytes.clear();
        runLengthDeflate(filtered.data(), first * stride, (first + count) * stride, 3, stride,
                         false, band_bytes);
        if (band_bytes.size() > static_cast<std::size_t>(end - o)) {
          throw Error("PNG: the run-length deflate outgrew its bound");
        }
        std::memcpy(o, band_bytes.data(), band_bytes.size());
        return band_bytes.size();
      });
}

// Adler-32 after the deflate data, then the IDAT length and CRC, then IEND.
void PngEncoder::Impl::finish(std::size_t deflated) {
  const std::size_t zlen = 2 + deflated + 4;
  unsigned char* o = out().data();
  put32(o + kIdatStart + 2 + deflated, adler);
  put32(o + kIdatStart - 8, static_cast<std::uint32_t>(zlen));
  const std::size_t crc_at = kIdatStart + zlen;
  put32(o + crc_at, static_cast<std::uint32_t>(crc32(0, o + kIdatStart - 4, zlen + 4)));
  static constexpr unsigned char kEnd[12] = {0,   0,   0,    0,    'I',  'E',
                                             'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  std::memcpy(o + crc_at + 4, kEnd, 12);
  out_size[current] = crc_at + 4 + 12;
}

bool keepsLastImage(PngCompression compression) {
  return compression == PngCompression::kDefault || compression == PngCompression::kFast;
}

const char* toString(PngCompression compression) {
  switch (compression) {
    case PngCompression::kDefault: return "default";
    case PngCompression::kFast: return "fast";
    case PngCompression::kStored: return "stored";
    case PngCompression::kSmall: return "small";
  }
  return "?";
}

PngCompression pngCompressionFromString(const std::string& name) {
  for (PngCompression c : {PngCompression::kDefault, PngCompression::kFast, PngCompression::kStored,
                           PngCompression::kSmall}) {
    if (name == toString(c)) return c;
  }
  throw Error("PNG compression must be default, fast, stored or small, got '" + name + "'");
}

PngEncoder::PngEncoder(PngCompression compression, bool keep_last_image)
    : impl_(std::make_unique<Impl>()) {
  impl_->compression = compression;
  impl_->keep_last = keep_last_image && keepsLastImage(compression);
  if (compression == PngCompression::kDefault) {
    // As compress2 at level 1: a 32 kB window, memory level 8, the default strategy; raw (the
    // zlib header and checksum are written here, the checksum faster).
    if (deflateInit2(&impl_->zs, kZlibLevel, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
      throw Error("PNG: zlib cannot start (out of memory?)");
    }
    impl_->deflating = true;
  }
}

PngEncoder::~PngEncoder() {
  if (impl_->deflating) deflateEnd(&impl_->zs);
}

bool PngEncoder::keepsLast() const { return impl_->keep_last; }

std::span<const unsigned char> PngEncoder::encode(const RgbImage& image) {
  Impl& m = *impl_;
  const Pixels pixels{image.pixels.data(), image.pixels.size(), image.width, image.height, 3,
                      std::nullopt};
  if (m.compression == PngCompression::kSmall) {  // stb takes the image as it is
    checkImage(pixels);
    m.out() = detail::encodePngStbDefault(image);
    m.out_size[m.current] = m.out().size();
    return {m.out().data(), m.out_size[m.current]};
  }
  return m.encode(pixels);
}

std::span<const unsigned char> PngEncoder::encode(const RgbaImage& image) {
  return impl_->encode(
      {image.pixels.data(), image.pixels.size(), image.width, image.height, 4, std::nullopt});
}

std::span<const unsigned char> PngEncoder::encode(const RgbaImage& image,
                                                  std::span<const RowSpan> changed) {
  int end = 0;
  for (const RowSpan& rows : changed) {
    if (rows.begin < end || rows.end <= rows.begin || rows.end > image.height) {
      throw Error("PNG: changed rows must be sorted, apart and inside the image");
    }
    end = rows.end;
  }
  if (!impl_->keep_last) {
    throw Error(std::string("PNG: this encoder (") + toString(impl_->compression) +
                " compression) keeps no last image to take unchanged rows from");
  }
  const Impl& m = *impl_;
  if (m.last_width != image.width || m.last_height != image.height || m.last_channels != 4) {
    throw Error("PNG: changed rows need the last image, of the same size");
  }
  return impl_->encode(
      {image.pixels.data(), image.pixels.size(), image.width, image.height, 4, changed});
}

std::span<const unsigned char> PngEncoder::Impl::encode(const Pixels& image) {
  checkImage(image);
  if (compression == PngCompression::kSmall) {
    // stb takes an RGB image whole. (An RGB image for kSmall went to stb in
    // encode(const RgbImage&).)
    rgb.resize(image.width, image.height);
    rgbaToRgb(image.data, rgb.pixels.data(), static_cast<std::size_t>(image.width) * image.height);
    out() = detail::encodePngStbDefault(rgb);
    out_size[current] = out().size();
    return {out().data(), out_size[current]};
  }
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  // Banded: a band's bound (deflateBound assumes no flush; the run-length deflate spends at
  // most 9 bits a byte) and its block ends and sync flush.
  const std::size_t band_filtered = (row_bytes + 1) * static_cast<std::size_t>(kBandRows);
  std::size_t band_bound = band_filtered / 8 * 9 + 16;  // kFast
  if (compression == PngCompression::kDefault) {
    band_bound = deflateBound(&zs, static_cast<uLong>(band_filtered)) + 6;
  }
  // The banded compressions copy from the last output: write the other buffer.
  if (keep_last) current = 1 - current;
  try {
    begin(image);
    adler = 1;
    switch (compression) {
      case PngCompression::kDefault: finish(deflateRows(image, band_bound)); break;
      case PngCompression::kFast: finish(runLengthRows(image, band_bound)); break;
      case PngCompression::kStored: finish(storeRows(image)); break;
      case PngCompression::kSmall: break;  // above
    }
  } catch (...) {
    // Half an image: nothing of it, nor of the image before, may be copied into the next.
    last_width = last_height = 0;
    throw;
  }
  return {out().data(), out_size[current]};
}

std::vector<unsigned char> encodePng(const RgbImage& image, PngCompression compression) {
  PngEncoder encoder(compression);
  const std::span<const unsigned char> bytes = encoder.encode(image);
  return {bytes.begin(), bytes.end()};
}

void writePng(const std::string& path, const RgbImage& image, PngCompression compression) {
  PngEncoder encoder(compression);
  const std::span<const unsigned char> bytes = encoder.encode(image);
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
