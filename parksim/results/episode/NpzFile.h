#pragma once
// Columns of doubles as a NumPy .npz archive: a ZIP file holding one deflated .npy array per
// column (NumPy's own format for several arrays, https://numpy.org/neps/nep-0001-npy-format.html),
// so `numpy.load(path)` reads it with nothing of parksim installed, and pandas through
// `pd.DataFrame(dict(np.load(path)))`. Values are the doubles themselves (little-endian
// IEEE 754), so they read back bit for bit; the archive takes about a quarter of the bytes of
// the same rows written as CSV text (docs/simulation.md, "Recorded rows").
//
// Deterministic: the same columns give the same bytes (every entry's ZIP time stamp is
// 1980-01-01 00:00, the format's zero). Written without ZIP64, so an archive stays under
// 4 GiB (kMaxNpzBytes). The reader takes what this writer writes and what numpy.savez and
// numpy.savez_compressed write for 1-D float64 arrays.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace parksim {

/// One named column of a table.
struct DataColumn {
  std::string name;
  std::vector<double> values;
};

/// Largest archive written or read, and largest array inflated from one (docs/limits.md).
inline constexpr std::uintmax_t kMaxNpzBytes = 1u << 30;

/// The archive's bytes: entry "<name>.npy" per column, in the given order. Columns may differ
/// in length. Throws Error when a name is empty, repeated or holds '/', or the archive would
/// exceed kMaxNpzBytes.
std::string npzArchive(const std::vector<DataColumn>& columns);

/// Writes npzArchive(columns) to `path` atomically. Throws Error.
void writeNpzFile(const std::string& path, const std::vector<DataColumn>& columns);

/// The columns of an archive's bytes, in archive order; `source` names it in messages. Throws
/// Error ("<source>: <entry>: <what>") on anything but 1-D little-endian float64 arrays
/// (stored or deflated), on a damaged archive or checksum, and past kMaxNpzBytes.
std::vector<DataColumn> parseNpz(std::string_view bytes, const std::string& source);

/// Reads the regular file at `path` (at most kMaxNpzBytes) with parseNpz. Throws Error.
std::vector<DataColumn> readNpzFile(const std::string& path);

}  // namespace parksim
