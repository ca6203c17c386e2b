#pragma once
// A deflate encoder (RFC 1951) for rendered images, four to five times faster than zlib's
// fastest level: it looks for two kinds of repeats only, the pixel before (flat areas) and the
// row above (what continues down the image), and writes them and the remaining bytes with the
// fixed Huffman codes, so there are no tables to build. Files are up to twice zlib's on busy
// images (no entropy coding of literals, no other matches) and about as large on rendered
// frames, far smaller than stored pixels. Any inflater
// reads them (tested against zlib's).

#include <cstddef>
#include <vector>

namespace parksim {

/// Appends to `out` a fixed-Huffman deflate block of data[begin, end), matching each position
/// against `pixel_bytes` and `row_bytes` before it (each at most 32768; 0: not used), also in
/// data before `begin`, which a reader has inflated by then. `final`: the stream's last block.
/// Otherwise an empty stored block follows, so that the next block starts on a byte boundary
/// (zlib's sync flush): blocks made apart can then be put one after the other.
void runLengthDeflate(const unsigned char* data, std::size_t begin, std::size_t end,
                      std::size_t pixel_bytes, std::size_t row_bytes, bool final,
                      std::vector<unsigned char>& out);

}  // namespace parksim
