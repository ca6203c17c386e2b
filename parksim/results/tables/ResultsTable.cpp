#include "parksim/results/tables/ResultsTable.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/results/tables/RowSeal.h"

namespace parksim {
namespace {

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

[[noreturn]] void failAppend(const std::string& path, const char* what) {
  throw Error(path + ": " + what + ": " + std::strerror(errno));
}

void writeAll(int fd, const std::string& path, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      failAppend(path, "write failed");
    }
    done += static_cast<std::size_t>(n);
  }
}

long long sizeOf(int fd, const std::string& path) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) failAppend(path, "cannot read");
  return static_cast<long long>(st.st_size);
}

std::string openError(const std::string& path) {
  return path + ": cannot open: " + std::strerror(errno);
}

// Why a row of the table cannot be resumed by a sweep expecting `expect`, or nothing.
std::optional<std::string> mismatch(const nlohmann::ordered_json& row,
                                    const TableExpectations& expect) {
  const std::string world = row.value("world", "");
  const auto it = expect.world_hashes.find(world);
  if (it != expect.world_hashes.end()) {
    const std::string hash = row.value(std::string(kWorldHashKey), "(none)");
    if (hash != it->second) {
      return "episode " + row.value("episode_id", "?") + " ran on another content of world '" +
             world + "' (world_hash " + hash + "; the world file now: " + it->second +
             "): the world file changed since; sweep into a new --out (or restore the file)";
    }
  }
  if (!expect.writer.empty()) {
    const std::string writer = rowWriter(row);
    if (writer != expect.writer) {
      return "episode " + row.value("episode_id", "?") + " was written by " + writer +
             ", not by this " + expect.writer +
             ": resuming would mix results of two builds; sweep into a new --out";
    }
  }
  return std::nullopt;
}

}  // namespace

std::string resultsLockPath(const std::string& dir) { return dir + "/.results.lock"; }

bool resultsTableBusy(const std::string& dir) {
  const int fd = ::open(resultsLockPath(dir).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool busy = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return busy;
}

ResultsTable::ResultsTable(const std::string& dir, const TableExpectations& expect,
                           double sync_interval_s)
    : jsonl_path_(dir + "/results.jsonl"),
      csv_path_(dir + "/results.csv"),
      sync_interval_s_(sync_interval_s) {
  ensureDirectory(dir);
  const std::string lock = resultsLockPath(dir);
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) throw Error(openError(lock));
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = errno == EWOULDBLOCK;
    const std::string why = std::strerror(errno);
    ::close(lock_fd_);
    throw Error(jsonl_path_ + ": " +
                (busy ? "another parksim sweep is writing this table (" + lock +
                            " is locked); wait for it or choose another --out"
                      : "cannot lock " + lock + ": " + why));
  }
  try {
    open(dir, expect);
  } catch (...) {
    for (int* fd : {&jsonl_fd_, &csv_fd_, &lock_fd_}) {
      if (*fd >= 0) ::close(*fd);
      *fd = -1;
    }
    throw;
  }
}

void ResultsTable::open(const std::string& dir, const TableExpectations& expect) {
  // One pass over both files: every row of results.jsonl checked, and results.csv followed
  // against the rendering of each row in the columns its header names.
  CsvFollower csv(csv_path_);
  bool csv_whole = false;  // results.csv so far is exactly the rendering of results.jsonl
  std::string header;
  std::set<std::string, std::less<>> csv_set;  // the set columns results.csv has
  if (csv.nextLine(header)) {
    const std::optional<std::vector<std::string>> set = setColumnsOfHeader(header);
    if (!set) {
      throw Error(csv_path_ +
                  ":1: has other columns than this parksim writes (a table from another "
                  "version?); use another --out directory");
    }
    set_columns_ = *set;
    columns_ = resultColumns(set_columns_);
    csv_set.insert(set->begin(), set->end());
    csv_whole = true;
  }
  // The set columns the table needs: the sweep's set: paths and those of the rows already in.
  std::set<std::string, std::less<>> wanted(expect.set_columns.begin(), expect.set_columns.end());
  std::size_t rows = 0;
  const TableScan scan = scanResultsJsonl(jsonl_path_, [&](const TableRow& r) {
    if (const std::optional<std::string> why = mismatch(r.row, expect)) {
      throw Error(jsonl_path_ + ":" + std::to_string(r.line) + ": " + *why);
    }
    done_[r.row["episode_id"].get<std::string>()] = r.row.value("met_tolerance", false);
    addSetKeys(r.row, wanted);
    ++rows;
    if (!csv_whole) return;
    const CsvFollower::Match m = csv.next(csvRow(r.row, columns_));
    if (m == CsvFollower::Match::kDiffers) {
      throw Error(csv_path_ + ":" + std::to_string(csv.line()) + ": differs from the row of " +
                  jsonl_path_ + ":" + std::to_string(r.line) + " (episode " +
                  r.row["episode_id"].get<std::string>() +
                  "): results.csv changed after parksim wrote it; results.jsonl is the "
                  "reference: remove results.csv and run again to rebuild it");
    }
    csv_whole = m == CsvFollower::Match::kSame;
  });
  if (scan.torn_tail) {
    std::filesystem::resize_file(jsonl_path_, scan.whole_bytes);
    repairs_.push_back(jsonl_path_ +
                       ": cut off a torn last row (a sweep stopped while writing it); that "
                       "episode runs again");
  }
  const bool other_columns = csv_whole && wanted != csv_set;
  if (!csv_whole || csv.hasMore() || other_columns) {
    const bool had_csv = std::filesystem::exists(csv_path_);
    set_columns_ = rebuildResultsCsv(dir, std::vector<std::string>(wanted.begin(), wanted.end()));
    columns_ = resultColumns(set_columns_);
    if (had_csv) {
      repairs_.push_back(
          csv_path_ + ": rebuilt from results.jsonl (" + std::to_string(rows) + " rows), " +
          (other_columns ? "with a column for every set: path of the sweep and its rows"
                         : "which it did not match at its end (a sweep stopped between the two "
                           "files)"));
    }
  }

  jsonl_fd_ = ::open(jsonl_path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (jsonl_fd_ < 0) throw Error(openError(jsonl_path_));
  csv_fd_ = ::open(csv_path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (csv_fd_ < 0) throw Error(openError(csv_path_));
  jsonl_size_ = sizeOf(jsonl_fd_, jsonl_path_);
  csv_size_ = sizeOf(csv_fd_, csv_path_);
  last_sync_s_ = nowSeconds();
}

ResultsTable::~ResultsTable() {
  for (int fd : {jsonl_fd_, csv_fd_}) {
    if (fd >= 0) {
      ::fdatasync(fd);
      ::close(fd);
    }
  }
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the lock
}

void ResultsTable::append(const nlohmann::ordered_json& row) {
  const std::string id = row.at("episode_id").get<std::string>();
  const SealedRow sealed = sealRow(row);
  const std::string jsonl_line = sealed.line + "\n";
  for (const auto& [key, value] : row.items()) {
    if (isSetKey(key) && !std::binary_search(set_columns_.begin(), set_columns_.end(), key)) {
      throw Error(csv_path_ + ": episode " + id + " has the set column " + key +
                  ", which the table was not opened with");
    }
  }
  const std::string csv_line = csvRow(row, columns_, sealed.checksum);
  // A failed write may have left part of the row: cut both files back to their whole rows.
  // (ftruncate frees space; it does not need any.)
  const auto take_back = [this] {
    const int saved = errno;
    (void)::ftruncate(jsonl_fd_, jsonl_size_);
    (void)::ftruncate(csv_fd_, csv_size_);
    errno = saved;
  };
  try {
    writeAll(jsonl_fd_, jsonl_path_, jsonl_line);
    writeAll(csv_fd_, csv_path_, csv_line);
  } catch (...) {
    take_back();
    throw;
  }
  jsonl_size_ += static_cast<long long>(jsonl_line.size());
  csv_size_ += static_cast<long long>(csv_line.size());
  done_[id] = row.value("met_tolerance", false);
  if (nowSeconds() - last_sync_s_ >= sync_interval_s_) sync();
}

void ResultsTable::sync() {
  if (::fdatasync(jsonl_fd_) != 0) failAppend(jsonl_path_, "cannot sync");
  if (::fdatasync(csv_fd_) != 0) failAppend(csv_path_, "cannot sync");
  last_sync_s_ = nowSeconds();
}

}  // namespace parksim
