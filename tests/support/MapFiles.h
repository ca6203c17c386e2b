#pragma once
// Test support: map files written from code, for the map readers' tests: binary and plain PGM,
// PNG (grey, grey + alpha, RGB, RGBA; through zlib, with its CRCs), text files, and a test
// folder that starts empty.

#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/TestPaths.h"

namespace parksim::testing {

/// An empty folder for one test's files.
inline std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path dir = testOutputDir(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// `rows` from the top, one byte per pixel.
inline void writePgm(const std::filesystem::path& path, const std::vector<std::vector<int>>& rows,
                     bool plain = false, int max_value = 255) {
  const std::size_t h = rows.size();
  const std::size_t w = rows.front().size();
  std::string s = std::string(plain ? "P2" : "P5") + "\n# test map\n" + std::to_string(w) + " " +
                  std::to_string(h) + "\n" + std::to_string(max_value) + "\n";
  for (const auto& row : rows) {
    for (const int v : row) {
      if (plain) {
        s += std::to_string(v) + " ";
      } else if (max_value > 255) {
        s += static_cast<char>(v >> 8);
        s += static_cast<char>(v & 0xff);
      } else {
        s += static_cast<char>(v);
      }
    }
    if (plain) s += "\n";
  }
  writeText(path, s);
}

/// `pixels` from the top, `channels` (1 to 4) bytes per pixel.
inline void writePng(const std::filesystem::path& path, int width, int height, int channels,
                     const std::vector<std::uint8_t>& pixels) {
  const auto be32 = [](std::string& s, std::uint32_t v) {
    for (int k = 3; k >= 0; --k) s += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  const auto chunk = [&](std::string& out, const char* type, const std::string& data) {
    be32(out, static_cast<std::uint32_t>(data.size()));
    const std::string body = std::string(type, 4) + data;
    out += body;
    be32(out, static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(body.data()),
                                               static_cast<uInt>(body.size()))));
  };
  std::string raw;
  for (int j = 0; j < height; ++j) {
    raw += '\0';  // no filter
    raw.append(reinterpret_cast<const char*>(pixels.data()) + std::size_t(j) * width * channels,
               std::size_t(width) * channels);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(size, '\0');
  compress(reinterpret_cast<Bytef*>(packed.data()), &size,
           reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()));
  packed.resize(size);
  static const int kColourType[] = {0, 0, 4, 2, 6};
  std::string ihdr;
  be32(ihdr, static_cast<std::uint32_t>(width));
  be32(ihdr, static_cast<std::uint32_t>(height));
  ihdr += static_cast<char>(8);
  ihdr += static_cast<char>(kColourType[channels]);
  ihdr += std::string(3, '\0');
  std::string png("\x89PNG\r\n\x1a\n", 8);
  chunk(png, "IHDR", ihdr);
  chunk(png, "IDAT", packed);
  chunk(png, "IEND", "");
  writeText(path, png);
}

}  // namespace parksim::testing
