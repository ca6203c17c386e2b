#include "parksim/results/tables/ResultsFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <tuple>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/results/tables/RowSeal.h"

namespace parksim {
namespace {

constexpr std::size_t kChunkBytes = 1u << 20;

[[noreturn]] void failErrno(const std::string& path, const char* what) {
  throw Error(path + ": " + what + ": " + std::strerror(errno));
}

// Opens a table file for reading: -1 when it does not exist. Only a regular file within the
// limit is read: a results.jsonl that was /dev/zero (a symlink) grew to 2 GB, a FIFO hung.
int openTableFile(const std::string& path, const char* what) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    if (errno == ENOENT) return -1;
    throw Error(path + ": cannot open " + what + ": " + std::strerror(errno));
  }
  struct stat st {};
  std::string problem;
  if (::fstat(fd, &st) != 0) {
    problem = std::string("cannot read ") + what + ": " + std::strerror(errno);
  } else if (S_ISDIR(st.st_mode)) {
    problem = std::string("is a directory, not a ") + what;
  } else if (!S_ISREG(st.st_mode)) {
    problem = std::string("is not a regular file (a device, pipe or socket), not a ") + what;
  } else if (static_cast<std::uintmax_t>(st.st_size) > kMaxResultsTableBytes) {
    problem = std::string(what) + " is " + std::to_string(st.st_size) +
              " bytes, more than the limit of " + std::to_string(kMaxResultsTableBytes) +
              " (docs/limits.md)";
  }
  if (!problem.empty()) {
    ::close(fd);
    throw Error(path + ": " + problem);
  }
  return fd;
}

// Reads `fd` into `buffer` from `end`, growing it; false at the end of the file.
bool readMore(int fd, const std::string& path, std::string& buffer, std::size_t& end,
              std::uint64_t& total) {
  if (buffer.size() - end < kChunkBytes / 2)
    buffer.resize(std::max(buffer.size() * 2, kChunkBytes));
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data() + end, buffer.size() - end);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) failErrno(path, "cannot read");
    end += static_cast<std::size_t>(n);
    total += static_cast<std::uint64_t>(n);
    if (total > kMaxResultsTableBytes) {
      throw Error(path + ": grew past the limit of " + std::to_string(kMaxResultsTableBytes) +
                  " bytes while it was read (docs/limits.md)");
    }
    return n > 0;
  }
}

// The lines of a file, one at a time, with a buffer of about one line (at least 1 MiB).
class LineReader {
 public:
  LineReader(const std::string& path, const char* what)
      : path_(path), fd_(openTableFile(path, what)) {}
  ~LineReader() {
    if (fd_ >= 0) ::close(fd_);
  }
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  bool exists() const { return fd_ >= 0; }

  // The next whole line (without its newline) and the offset of its first byte; false at the
  // end, with torn() telling whether bytes without a final newline were left.
  bool next(std::string_view& line, std::uint64_t& offset) {
    if (fd_ < 0) return false;
    for (;;) {
      const char* nl =
          static_cast<const char*>(std::memchr(buffer_.data() + begin_, '\n', end_ - begin_));
      if (nl != nullptr) {
        const std::size_t length = static_cast<std::size_t>(nl - (buffer_.data() + begin_));
        line = std::string_view(buffer_.data() + begin_, length);
        offset = offset_;
        begin_ += length + 1;
        offset_ += length + 1;
        return true;
      }
      if (eof_) {
        torn_ = end_ > begin_;
        return false;
      }
      // Keep the partial line and read on.
      buffer_.erase(0, begin_);
      end_ -= begin_;
      begin_ = 0;
      eof_ = !readMore(fd_, path_, buffer_, end_, total_);
    }
  }
  bool torn() const { return torn_; }

 private:
  std::string path_;
  int fd_;
  std::string buffer_;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  std::uint64_t offset_ = 0;
  std::uint64_t total_ = 0;
  bool eof_ = false;
  bool torn_ = false;
};

// What is wrong with the type of a key of the record (EpisodeRecord.h), or nothing. A
// hand-edited or foreign row ("met_tolerance": "yes") was a JSON type error, exit 3.
std::optional<std::string> badKeyType(const nlohmann::ordered_json& row) {
  for (const auto& [key, value] : row.items()) {
    if (value.is_null()) continue;
    const EpisodeField* f = findField(key);
    if (f == nullptr) continue;
    const char* what = nullptr;
    switch (f->type) {
      case FieldType::kString: what = value.is_string() ? nullptr : "a string"; break;
      case FieldType::kBoolean: what = value.is_boolean() ? nullptr : "true or false"; break;
      case FieldType::kInteger:
      case FieldType::kNumber: what = value.is_number() ? nullptr : "a number"; break;
      case FieldType::kList: what = value.is_array() ? nullptr : "a list"; break;
      case FieldType::kObject: what = value.is_object() ? nullptr : "an object"; break;
    }
    if (what != nullptr) {
      const std::string got = value.dump();
      return "key '" + key + "' must be " + what + ", got " + got.substr(0, 40) +
             (got.size() > 40 ? "..." : "");
    }
  }
  if (const auto it = row.find("plan_cost_history"); it != row.end() && it->is_array()) {
    bool ok = true;
    for (const nlohmann::ordered_json& sample : *it) {
      ok = ok && sample.is_array() && sample.size() == 3 && sample[0].is_number() &&
           sample[1].is_number() && sample[2].is_number();
    }
    if (!ok)
      return std::string("key 'plan_cost_history' must be a list of [time_s, iteration, cost_m]");
  }
  return std::nullopt;
}

std::string csvCell(const nlohmann::ordered_json& v) {
  std::string s;
  if (v.is_null()) return s;
  if (v.is_string()) {
    s = v.get<std::string>();
  } else if (v.is_boolean()) {
    s = v.get<bool>() ? "true" : "false";
  } else if (v.is_array()) {
    for (const auto& item : v) {
      if (!s.empty()) s += '|';
      s += item.is_string() ? item.get<std::string>() : item.dump();
    }
  } else {
    s = v.dump();
  }
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (const char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  q += '"';
  return q;
}

}  // namespace

std::vector<std::string> resultColumns(const std::vector<std::string>& set_columns) {
  return recordColumns(set_columns);
}

std::optional<std::vector<std::string>> setColumnsOfHeader(std::string_view header) {
  std::vector<std::string> names;
  for (std::size_t start = 0;;) {
    const std::size_t comma = std::min(header.find(',', start), header.size());
    names.emplace_back(header.substr(start, comma - start));
    if (comma == header.size()) break;
    start = comma + 1;
  }
  const std::vector<std::string> fixed = resultColumns();
  const std::size_t at = setColumnsPosition();
  if (names.size() < fixed.size()) return std::nullopt;
  const std::size_t extra = names.size() - fixed.size();
  std::vector<std::string> set(names.begin() + static_cast<long>(at),
                               names.begin() + static_cast<long>(at + extra));
  if (!std::is_sorted(set.begin(), set.end()) ||
      std::adjacent_find(set.begin(), set.end()) != set.end() ||
      !std::all_of(set.begin(), set.end(), [](const std::string& k) { return isSetKey(k); }) ||
      resultColumns(set) != names) {
    return std::nullopt;
  }
  return set;
}

void addSetKeys(const nlohmann::ordered_json& row, std::set<std::string, std::less<>>& keys) {
  for (const auto& [key, value] : row.items()) {
    if (keys.find(key) == keys.end() && isSetKey(key)) keys.insert(key);
  }
}

bool isTimingKey(std::string_view key) {
  const EpisodeField* f = findField(key);
  return f != nullptr && f->group == FieldGroup::kTiming;
}

nlohmann::ordered_json withoutTiming(const nlohmann::ordered_json& row) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : row.items()) {
    if (!isTimingKey(key) && key != kRowChecksumKey) out[key] = value;
  }
  return out;
}

std::string csvHeader(const std::vector<std::string>& columns) {
  std::string s;
  for (const std::string& c : columns) {
    if (!s.empty()) s += ',';
    s += c;
  }
  s += '\n';
  return s;
}

std::string csvRow(const nlohmann::ordered_json& row, const std::vector<std::string>& columns,
                   std::string_view checksum) {
  std::string s;
  bool first = true;
  for (const std::string& c : columns) {
    if (!first) s += ',';
    first = false;
    const auto it = row.find(c);
    if (it != row.end()) {
      s += csvCell(*it);
    } else if (c == kRowChecksumKey) {
      s += checksum;
    }
  }
  s += '\n';
  return s;
}

namespace {

// What is wrong with one line of results.jsonl (parsed into `row` when it is JSON), or nothing.
std::optional<std::string> rowProblem(std::string_view text, nlohmann::ordered_json& row) {
  // The seal first: a changed byte that also breaks the JSON is still a changed row.
  if (std::optional<std::string> problem = sealProblem(text)) return problem;
  row = nlohmann::ordered_json::parse(text, nullptr, false);
  if (!row.is_object() || !row.contains("episode_id") || !row["episode_id"].is_string()) {
    return std::string("not a results row (a JSON object with an episode_id)");
  }
  return badKeyType(row);
}

}  // namespace

TableScan scanResultsJsonl(const std::string& path, const TableRowVisitor& visit,
                           const TableProblemVisitor& on_problem) {
  LineReader reader(path, "results table");
  TableScan scan;
  std::string_view text;
  std::uint64_t offset = 0;
  std::size_t line = 0;
  nlohmann::ordered_json row;
  while (reader.next(text, offset)) {
    ++line;
    scan.whole_bytes = offset + text.size() + 1;
    if (const std::optional<std::string> problem = rowProblem(text, row)) {
      if (!on_problem) throw Error(path + ":" + std::to_string(line) + ": " + *problem);
      on_problem(line, *problem);
      continue;
    }
    if (visit) visit(TableRow{row, text, line, offset});
    ++scan.rows;
  }
  scan.torn_tail = reader.torn();
  return scan;
}

std::vector<nlohmann::ordered_json> readResultsJsonl(const std::string& path) {
  std::vector<nlohmann::ordered_json> rows;
  scanResultsJsonl(path, [&rows](const TableRow& r) { rows.push_back(r.row); });
  return rows;
}

VerifiedTable readVerifiedTable(const std::string& path) {
  VerifiedTable t;
  std::error_code ec;
  t.path = std::filesystem::is_directory(path, ec) ? path + "/results.jsonl" : path;
  if (!std::filesystem::exists(t.path, ec)) {
    throw Error(t.path + ": no such file (not a sweep's results table)");
  }
  const TableScan scan = scanResultsJsonl(t.path, [&t](const TableRow& r) {
    t.origins.add(r.row, t.path, r.line);
    t.rows.push_back(r.row);
  });
  t.torn_tail = scan.torn_tail;
  return t;
}

void TableOrigins::add(const nlohmann::ordered_json& row, const std::string& path,
                       std::size_t line) {
  const auto text = [&row](std::string_view key) {
    const auto it = row.find(key);
    return it != row.end() && it->is_string() ? it->get<std::string>() : std::string("?");
  };
  const auto note = [&](std::map<std::string, std::string>& seen, const std::string& key) {
    if (seen.find(key) != seen.end()) return;
    const std::string where = path + ":" + std::to_string(line);
    seen.emplace(key, where);
    seen_at_.emplace(where, order_++);
  };
  note(world_hashes_[text("world")], text(kWorldHashKey));
  note(writers_, rowWriter(row));
}

std::vector<std::string> TableOrigins::mixes() const {
  std::vector<std::string> out;
  // Variants in the order they were first seen: (order, where, value).
  const auto ordered = [this](const std::map<std::string, std::string>& seen) {
    std::vector<std::tuple<std::size_t, std::string, std::string>> v;
    for (const auto& [value, where] : seen) v.emplace_back(seen_at_.at(where), where, value);
    std::sort(v.begin(), v.end());
    return v;
  };
  for (const auto& [world, hashes] : world_hashes_) {
    if (hashes.size() < 2) continue;
    const auto v = ordered(hashes);
    for (std::size_t i = 1; i < v.size(); ++i) {
      out.push_back(std::get<1>(v[i]) + ": world '" + world + "' has another content (world_hash " +
                    std::get<2>(v[i]) + ") than at " + std::get<1>(v[0]) + " (" +
                    std::get<2>(v[0]) + "): the world file changed between runs");
    }
  }
  if (writers_.size() > 1) {
    const auto v = ordered(writers_);
    for (std::size_t i = 1; i < v.size(); ++i) {
      out.push_back(std::get<1>(v[i]) + ": written by " + std::get<2>(v[i]) + ", the row at " +
                    std::get<1>(v[0]) + " by " + std::get<2>(v[0]) + ": results of two builds");
    }
  }
  return out;
}

CsvFollower::CsvFollower(const std::string& path)
    : fd_(openTableFile(path, "results table")), eof_(fd_ < 0), path_(path) {}

CsvFollower::~CsvFollower() {
  if (fd_ >= 0) ::close(fd_);
}

bool CsvFollower::fill() {
  if (eof_) return false;
  if (pos_ > 0) {
    buffer_.erase(0, pos_);
    pos_ = 0;
  }
  std::size_t end = buffer_.size();
  buffer_.resize(end + kChunkBytes);
  eof_ = !readMore(fd_, path_, buffer_, end, total_);
  buffer_.resize(end);
  return !eof_;
}

CsvFollower::Match CsvFollower::next(std::string_view expected) {
  std::size_t matched = 0;
  while (matched < expected.size()) {
    const auto stop = [&](Match m) {
      line_ += static_cast<std::size_t>(
          std::count(expected.begin(), expected.begin() + static_cast<long>(matched), '\n'));
      return m;
    };
    // fill() keeps the bytes from pos_ on, so `matched` still counts from pos_.
    if (pos_ + matched >= buffer_.size() && !fill()) return stop(Match::kEnded);
    if (pos_ + matched >= buffer_.size()) continue;
    if (buffer_[pos_ + matched] != expected[matched]) return stop(Match::kDiffers);
    ++matched;
  }
  pos_ += matched;
  line_ += static_cast<std::size_t>(std::count(expected.begin(), expected.end(), '\n'));
  return Match::kSame;
}

void CsvFollower::skipLine() {
  for (;;) {
    const std::size_t nl = buffer_.find('\n', pos_);
    if (nl != std::string::npos) {
      pos_ = nl + 1;
      ++line_;
      return;
    }
    pos_ = buffer_.size();
    if (!fill()) return;
  }
}

bool CsvFollower::nextLine(std::string& line) {
  for (;;) {
    const std::size_t nl = buffer_.find('\n', pos_);
    if (nl != std::string::npos) {
      line.assign(buffer_, pos_, nl - pos_);
      pos_ = nl + 1;
      ++line_;
      return true;
    }
    if (!fill()) return false;
  }
}

bool CsvFollower::hasMore() {
  if (pos_ < buffer_.size()) return true;
  while (fill()) {
    if (pos_ < buffer_.size()) return true;
  }
  return pos_ < buffer_.size();
}

namespace {

// A table file written beside its place and renamed over it when complete.
struct TempTableFile {
  std::string path;  // the table
  std::string tmp;   // written first
  int fd = -1;
  std::string pending;

  explicit TempTableFile(std::string table) : path(std::move(table)), tmp(path + ".tmp") {
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) failErrno(path, "cannot write");
  }
  ~TempTableFile() {
    if (fd >= 0) ::close(fd);
  }
  TempTableFile(const TempTableFile&) = delete;
  TempTableFile& operator=(const TempTableFile&) = delete;
  void flush() {
    std::size_t done = 0;
    while (done < pending.size()) {
      const ssize_t n = ::write(fd, pending.data() + done, pending.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) failErrno(path, "write failed");
      done += static_cast<std::size_t>(n);
    }
    pending.clear();
  }
  void add(std::string_view text) {
    pending += text;
    if (pending.size() >= kChunkBytes) flush();
  }
  void finish() {
    flush();
    if (::fdatasync(fd) != 0) failErrno(path, "cannot sync");
    const int closed = ::close(fd);
    fd = -1;
    if (closed != 0) failErrno(path, "write failed");
  }
  void rename() {
    if (::rename(tmp.c_str(), path.c_str()) != 0) failErrno(path, "cannot rename into place");
  }
};

}  // namespace

struct ResultsTableWriter::TempFile : TempTableFile {
  using TempTableFile::TempTableFile;
};

ResultsTableWriter::ResultsTableWriter(const std::string& dir,
                                       const std::vector<std::string>& set_columns)
    : dir_(dir), columns_(resultColumns(set_columns)) {
  ensureDirectory(dir);
  jsonl_ = std::make_unique<TempFile>(dir + "/results.jsonl");
  try {
    csv_ = std::make_unique<TempFile>(dir + "/results.csv");
    csv_->add(csvHeader(columns_));
  } catch (...) {
    ::unlink(jsonl_->tmp.c_str());
    throw;
  }
}

ResultsTableWriter::~ResultsTableWriter() {
  if (committed_) return;
  for (TempFile* f : {jsonl_.get(), csv_.get()}) {
    if (f != nullptr) ::unlink(f->tmp.c_str());
  }
}

void ResultsTableWriter::add(std::string_view sealed_line, const nlohmann::ordered_json& row) {
  jsonl_->add(sealed_line);
  jsonl_->add("\n");
  csv_->add(csvRow(row, columns_));
}

void ResultsTableWriter::commit() {
  jsonl_->finish();
  csv_->finish();
  // Both complete: renaming needs no space, so the pair is replaced together.
  jsonl_->rename();
  csv_->rename();
  committed_ = true;
}

std::vector<std::string> rebuildResultsCsv(const std::string& dir,
                                           const std::vector<std::string>& set_columns) {
  const std::string jsonl = dir + "/results.jsonl";
  // Two passes, one row in memory: the columns first, then the rows.
  std::set<std::string, std::less<>> keys(set_columns.begin(), set_columns.end());
  scanResultsJsonl(jsonl, [&keys](const TableRow& r) { addSetKeys(r.row, keys); });
  std::vector<std::string> set(keys.begin(), keys.end());
  const std::vector<std::string> columns = resultColumns(set);
  TempTableFile csv(dir + "/results.csv");
  try {
    csv.add(csvHeader(columns));
    scanResultsJsonl(jsonl, [&](const TableRow& r) { csv.add(csvRow(r.row, columns)); });
    csv.finish();
    csv.rename();
  } catch (...) {
    ::unlink(csv.tmp.c_str());
    throw;
  }
  return set;
}

void writeResultsTable(const std::string& dir, const std::vector<nlohmann::ordered_json>& rows) {
  std::set<std::string, std::less<>> keys;
  for (const nlohmann::ordered_json& row : rows) addSetKeys(row, keys);
  ResultsTableWriter writer(dir, std::vector<std::string>(keys.begin(), keys.end()));
  for (const nlohmann::ordered_json& row : rows) {
    if (row.contains(kRowChecksumKey)) {
      const std::string line = row.dump();
      if (const std::optional<std::string> problem = sealProblem(line)) {
        throw Error(dir + ": row " + row.value("episode_id", "?") + ": " + *problem);
      }
      writer.add(line, row);
    } else {
      const SealedRow sealed = sealRow(row);
      nlohmann::ordered_json with = row;
      with[std::string(kRowChecksumKey)] = sealed.checksum;
      writer.add(sealed.line, with);
    }
  }
  writer.commit();
}

}  // namespace parksim
