#include "parksim/results/episode/NpzFile.h"

#include <zlib.h>

#include <bit>
#include <cstring>
#include <set>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"

namespace parksim {

namespace {

constexpr std::uint32_t kLocalHeader = 0x04034b50;
constexpr std::uint32_t kCentralHeader = 0x02014b50;
constexpr std::uint32_t kEndOfCentral = 0x06054b50;
constexpr std::uint16_t kVersion = 20;  // 2.0: deflate
constexpr std::uint16_t kDeflate = 8;
constexpr std::uint16_t kStored = 0;
constexpr std::uint16_t kDosDate = 0x21;  // 1980-01-01, the format's earliest date
constexpr char kNpyMagic[] = "\x93NUMPY";

void put16(std::string& out, std::uint32_t v) {
  out += static_cast<char>(v & 0xFF);
  out += static_cast<char>((v >> 8) & 0xFF);
}

void put32(std::string& out, std::uint32_t v) {
  put16(out, v & 0xFFFF);
  put16(out, v >> 16);
}

std::uint32_t get16(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8;
}

std::uint32_t get32(std::string_view b, std::size_t at) {
  return get16(b, at) | get16(b, at + 2) << 16;
}

// The .npy bytes of one column: version 1.0 header padded to a multiple of 64 bytes, as NumPy
// writes it, then the doubles little-endian.
std::string npyArray(const std::vector<double>& values) {
  std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" +
                     std::to_string(values.size()) + ",), }";
  const std::size_t unpadded = 10 + dict.size() + 1;
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict += '\n';
  std::string out(kNpyMagic, 6);
  out += '\x01';
  out += '\x00';
  put16(out, static_cast<std::uint32_t>(dict.size()));
  out += dict;
  const std::size_t at = out.size();
  out.resize(at + 8 * values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint64_t bits = std::bit_cast<std::uint64_t>(values[i]);
    for (int k = 0; k < 8; ++k) out[at + 8 * i + k] = static_cast<char>((bits >> (8 * k)) & 0xFF);
  }
  return out;
}

std::string deflateRaw(const std::string& in) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) !=
      Z_OK) {
    throw Error("npz: cannot start zlib's deflate");
  }
  std::string out(deflateBound(&z, static_cast<uLong>(in.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw Error("npz: zlib's deflate failed");
  return out;
}

std::uint32_t crc(std::string_view data) {
  return static_cast<std::uint32_t>(
      crc32(0L, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size())));
}

// The fields local and central headers share, from "version needed" to the extra length.
void putEntryFields(std::string& out, std::uint32_t checksum, std::size_t packed, std::size_t size,
                    const std::string& name) {
  put16(out, kVersion);
  put16(out, 0);  // flags
  put16(out, kDeflate);
  put16(out, 0);  // time 00:00
  put16(out, kDosDate);
  put32(out, checksum);
  put32(out, static_cast<std::uint32_t>(packed));
  put32(out, static_cast<std::uint32_t>(size));
  put16(out, static_cast<std::uint32_t>(name.size()));
  put16(out, 0);  // extra field length
}

[[noreturn]] void damaged(const std::string& source, const std::string& what) {
  throw Error(source + ": not a readable .npz archive: " + what);
}

std::string inflateRaw(std::string_view in, std::size_t size, const std::string& where) {
  std::string out(size, '\0');
  z_stream z{};
  if (inflateInit2(&z, -MAX_WBITS) != Z_OK) throw Error(where + ": cannot start zlib's inflate");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = inflate(&z, Z_FINISH);
  const std::size_t produced = z.total_out;
  inflateEnd(&z);
  if (rc != Z_STREAM_END || produced != size) throw Error(where + ": damaged deflate data");
  return out;
}

// The doubles of one .npy array; only 1-D little-endian float64 in C order.
std::vector<double> parseNpy(std::string_view b, const std::string& where) {
  if (b.size() < 10 || b.substr(0, 6) != std::string_view(kNpyMagic, 6)) {
    throw Error(where + ": not a .npy array");
  }
  const int major = static_cast<unsigned char>(b[6]);
  std::size_t header_len = 0;
  std::size_t at = 0;
  if (major == 1) {
    header_len = get16(b, 8);
    at = 10;
  } else if ((major == 2 || major == 3) && b.size() >= 12) {
    header_len = get32(b, 8);
    at = 12;
  } else {
    throw Error(where + ": .npy version " + std::to_string(major) + " is not supported");
  }
  if (header_len > b.size() - at) throw Error(where + ": .npy header runs past the data");
  const std::string_view header = b.substr(at, header_len);
  const auto has = [&](std::string_view s) { return header.find(s) != std::string_view::npos; };
  if (!(has("'descr': '<f8'") && has("'fortran_order': False"))) {
    throw Error(where + ": not a little-endian float64 array ('<f8' in C order)");
  }
  const std::size_t shape = header.find("'shape': (");
  if (shape == std::string_view::npos) throw Error(where + ": .npy header has no shape");
  std::size_t pos = shape + 10;
  std::uint64_t n = 0;
  std::size_t digits = 0;
  while (pos < header.size() && header[pos] >= '0' && header[pos] <= '9' && digits < 12) {
    n = 10 * n + static_cast<std::uint64_t>(header[pos] - '0');
    ++pos, ++digits;
  }
  if (digits == 0 || pos + 1 >= header.size() || header[pos] != ',' || header[pos + 1] != ')') {
    throw Error(where + ": not a one-dimensional array");
  }
  const std::string_view data = b.substr(at + header_len);
  if (data.size() != 8 * n) throw Error(where + ": the array's data is not its shape's size");
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t bits = 0;
    for (int k = 7; k >= 0; --k) bits = bits << 8 | static_cast<unsigned char>(data[8 * i + k]);
    values[i] = std::bit_cast<double>(bits);
  }
  return values;
}

}  // namespace

std::string npzArchive(const std::vector<DataColumn>& columns) {
  std::string out;
  std::string central;
  std::set<std::string> names;
  for (const DataColumn& c : columns) {
    if (c.name.empty() || c.name.find('/') != std::string::npos || !names.insert(c.name).second) {
      throw Error("npz: column name '" + c.name + "' is empty, holds '/' or is repeated");
    }
    const std::string name = c.name + ".npy";
    const std::string npy = npyArray(c.values);
    const std::string packed = deflateRaw(npy);
    const std::size_t offset = out.size();
    if (offset + packed.size() + npy.size() + 2 * name.size() + 128 > kMaxNpzBytes) {
      throw Error("npz: more than " + std::to_string(kMaxNpzBytes >> 20) + " MiB of columns");
    }
    const std::uint32_t checksum = crc(npy);
    put32(out, kLocalHeader);
    putEntryFields(out, checksum, packed.size(), npy.size(), name);
    out += name;
    out += packed;
    put32(central, kCentralHeader);
    put16(central, kVersion);  // made by: MS-DOS attributes, version 2.0
    putEntryFields(central, checksum, packed.size(), npy.size(), name);
    put16(central, 0);  // comment length
    put16(central, 0);  // disk number
    put16(central, 0);  // internal attributes
    put32(central, 0);  // external attributes
    put32(central, static_cast<std::uint32_t>(offset));
    central += name;
  }
  const std::size_t central_at = out.size();
  out += central;
  put32(out, kEndOfCentral);
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<std::uint32_t>(columns.size()));
  put16(out, static_cast<std::uint32_t>(columns.size()));
  put32(out, static_cast<std::uint32_t>(central.size()));
  put32(out, static_cast<std::uint32_t>(central_at));
  put16(out, 0);  // comment length
  return out;
}

void writeNpzFile(const std::string& path, const std::vector<DataColumn>& columns) {
  writeFileAtomically(path, npzArchive(columns));
}

std::vector<DataColumn> parseNpz(std::string_view b, const std::string& source) {
  if (b.size() > kMaxNpzBytes) damaged(source, "larger than the limit");
  // The end record is the last 22 bytes unless the archive has a comment (at most 64 KiB).
  if (b.size() < 22) damaged(source, "too short");
  const std::size_t lowest = b.size() > 22 + 0xFFFF ? b.size() - 22 - 0xFFFF : 0;
  std::size_t end = std::string_view::npos;
  for (std::size_t i = b.size() - 21; i-- > lowest;) {
    if (get32(b, i) == kEndOfCentral) {
      end = i;
      break;
    }
  }
  if (end == std::string_view::npos) damaged(source, "no end of central directory");
  const std::size_t count = get16(b, end + 10);
  const std::size_t central_size = get32(b, end + 12);
  const std::size_t central_at = get32(b, end + 16);
  if (central_at > end || central_size > end - central_at) {
    damaged(source, "central directory out of range");
  }
  std::vector<DataColumn> columns;
  std::uintmax_t inflated = 0;
  std::size_t at = central_at;
  for (std::size_t k = 0; k < count; ++k) {
    if (at + 46 > end || get32(b, at) != kCentralHeader) damaged(source, "bad central directory");
    const std::uint32_t method = get16(b, at + 10);
    const std::uint32_t checksum = get32(b, at + 16);
    const std::size_t packed = get32(b, at + 20);
    const std::size_t size = get32(b, at + 24);
    const std::size_t name_len = get16(b, at + 28);
    const std::size_t skip = get16(b, at + 30) + get16(b, at + 32);
    const std::size_t local = get32(b, at + 42);
    if (at + 46 + name_len + skip > end) damaged(source, "bad central directory");
    const std::string name(b.substr(at + 46, name_len));
    at += 46 + name_len + skip;
    const std::string where = source + ": " + name;
    if (local + 30 > central_at || get32(b, local) != kLocalHeader) {
      damaged(source, "entry " + name + " has no local header");
    }
    const std::size_t data_at = local + 30 + get16(b, local + 26) + get16(b, local + 28);
    if (data_at > central_at || packed > central_at - data_at) {
      damaged(source, "entry " + name + " runs past the archive");
    }
    inflated += size;
    if (inflated > kMaxNpzBytes) damaged(source, "its arrays exceed the limit");
    const std::string_view data = b.substr(data_at, packed);
    std::string npy;
    if (method == kStored && packed == size) {
      npy = std::string(data);
    } else if (method == kDeflate) {
      npy = inflateRaw(data, size, where);
    } else {
      throw Error(where + ": compression method " + std::to_string(method) + " not supported");
    }
    if (crc(npy) != checksum) throw Error(where + ": checksum mismatch (damaged file)");
    if (name.size() < 5 || name.compare(name.size() - 4, 4, ".npy") != 0) {
      throw Error(where + ": not a .npy entry");
    }
    columns.push_back({name.substr(0, name.size() - 4), parseNpy(npy, where)});
  }
  return columns;
}

std::vector<DataColumn> readNpzFile(const std::string& path) {
  return parseNpz(readInputFile(path, kMaxNpzBytes, "npz archive"), path);
}

}  // namespace parksim
