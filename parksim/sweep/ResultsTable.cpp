#include "parksim/sweep/ResultsTable.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/core/InputFile.h"

namespace parksim {
namespace {

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The table's text, or "" when there is none yet. Only a regular file within the limit is read:
// a results.jsonl that is /dev/zero (a symlink) grew to 2 GB, a FIFO hung.
std::string readAll(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return {};
  return readInputFile(path, kMaxResultsTableBytes, "results table");
}

[[noreturn]] void failErrno(const std::string& path, const char* what) {
  throw Error(path + ": " + what + ": " + std::strerror(errno));
}

void writeAll(int fd, const std::string& path, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      failErrno(path, "cannot write");
    }
    done += static_cast<std::size_t>(n);
  }
}

// The text up to and including its last newline: what a torn write leaves after it goes.
std::size_t wholeLinesLength(const std::string& text) {
  const std::size_t nl = text.rfind('\n');
  return nl == std::string::npos ? 0 : nl + 1;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string::npos) break;
    out.push_back(text.substr(start, nl - start));
    start = nl + 1;
  }
  return out;
}

// Rows of a jsonl text that ends with a newline. Sets `good_length` to the bytes of the rows
// kept: a last line that does not parse is a torn write and is dropped.
// What is wrong with the type of a key parksim reads back from a row (sweep, merge, report),
// or nothing. A hand-edited or foreign row ("met_tolerance": "yes") was a JSON type error,
// exit 3.
std::optional<std::string> badKeyType(const nlohmann::ordered_json& row) {
  using Json = nlohmann::ordered_json;
  const auto check = [&row](std::initializer_list<const char*> keys, bool (Json::*is)() const,
                            const char* what) -> std::optional<std::string> {
    for (const char* key : keys) {
      const auto it = row.find(key);
      if (it != row.end() && !it->is_null() && !((*it).*is)()) {
        const std::string got = it->dump();
        return "key '" + std::string(key) + "' must be " + what + ", got " + got.substr(0, 40) +
               (got.size() > 40 ? "..." : "");
      }
    }
    return std::nullopt;
  };
  if (auto p = check({"world", "world_file", "planner", "steering", "tracking", "timing", "realism",
                      "status", "failure", "plan_status", "host"},
                     &Json::is_string, "a string")) {
    return p;
  }
  if (auto p = check({"met_tolerance", "smooth", "plan_solved", "goal_reached"}, &Json::is_boolean,
                     "true or false")) {
    return p;
  }
  if (auto p =
          check({"seed", "noise_seed", "max_iterations", "plan_max_iterations", "plan_iterations",
                 "plan_tree_size", "plan_goal_tree_size", "plan_cusps", "plan_collision_queries"},
                &Json::is_number, "a number")) {
    return p;
  }
  if (const auto it = row.find("plan_cost_history"); it != row.end() && !it->is_null()) {
    bool ok = it->is_array();
    for (const Json& sample : ok ? *it : Json::array()) {
      ok = ok && sample.is_array() && sample.size() == 3 && sample[0].is_number() &&
           sample[1].is_number() && sample[2].is_number();
    }
    if (!ok)
      return std::string("key 'plan_cost_history' must be a list of [time_s, iteration, cost_m]");
  }
  return std::nullopt;
}

std::vector<nlohmann::ordered_json> parseRows(const std::string& path, const std::string& text,
                                              std::size_t& good_length) {
  std::vector<nlohmann::ordered_json> rows;
  const std::vector<std::string> all = lines(text);
  good_length = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::parse(all[i], nullptr, false);
    const bool ok = row.is_object() && row.contains("episode_id") && row["episode_id"].is_string();
    if (!ok) {
      if (i + 1 == all.size()) break;
      throw Error(path + ":" + std::to_string(i + 1) + ": not a results row");
    }
    if (const std::optional<std::string> problem = badKeyType(row)) {
      throw Error(path + ":" + std::to_string(i + 1) + ": " + *problem);
    }
    rows.push_back(std::move(row));
    good_length += all[i].size() + 1;
  }
  return rows;
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

std::string openError(const std::string& path) {
  return path + ": cannot open: " + std::strerror(errno);
}

}  // namespace

const std::vector<std::string>& resultColumns() {
  static const std::vector<std::string> columns = {
      "episode_id", "world", "world_file", "planner", "steering", "smooth", "seed",
      "max_iterations", "tracking", "timing", "realism", "noise_seed", "start_dx_m", "start_dy_m",
      "start_dyaw_deg", "goal_dx_m", "goal_dy_m", "goal_dyaw_deg",
      // outcome
      "status", "met_tolerance", "failure",
      // plan
      "plan_status", "plan_solved", "plan_max_iterations", "plan_iterations", "plan_tree_size",
      "plan_goal_tree_size", "plan_collision_queries", "plan_cost_m", "plan_path_length_m",
      "plan_duration_s", "plan_cusps", "plan_first_solution_iteration",
      // simulation
      "max_pos_err_m", "rms_pos_err_m", "final_pos_err_m", "max_heading_err_deg",
      "rms_heading_err_deg", "final_heading_err_deg", "final_x_m", "final_y_m", "final_theta_rad",
      "goal_pos_err_m", "goal_heading_err_deg", "goal_reached", "contacts", "first_contact_t_s",
      "first_contact_body", "contact_bodies", "max_parked_displacement_m", "sim_time_s", "steps",
      "ended_at_rest",
      // realism layers (empty for the ideal robot's episodes that do not report them)
      "estimator", "max_est_pos_err_m", "rms_est_pos_err_m", "max_est_heading_err_deg",
      "final_est_pos_err_m", "max_slip_mps", "rms_slip_mps", "slip_fraction", "max_motor_torque_nm",
      "max_motor_effort", "pose_samples_dropped",
      // timing
      "plan_time_s", "plan_first_solution_s", "sim_wall_s", "episode_wall_s",
      // provenance
      "parksim_version", "git_commit", "git_dirty", "build_type", "compiler", "bullet_precision",
      "host"};
  return columns;
}

bool isTimingKey(std::string_view key) {
  return key == "plan_time_s" || key == "plan_first_solution_s" || key == "sim_wall_s" ||
         key == "episode_wall_s" || key == "plan_cost_history" || key == "plan_phase_times_s";
}

nlohmann::ordered_json withoutTiming(const nlohmann::ordered_json& row) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : row.items()) {
    if (!isTimingKey(key)) out[key] = value;
  }
  return out;
}

std::string csvHeader() {
  std::string s;
  for (const std::string& c : resultColumns()) {
    if (!s.empty()) s += ',';
    s += c;
  }
  s += '\n';
  return s;
}

std::string csvRow(const nlohmann::ordered_json& row) {
  std::string s;
  bool first = true;
  for (const std::string& c : resultColumns()) {
    if (!first) s += ',';
    first = false;
    const auto it = row.find(c);
    if (it != row.end()) s += csvCell(*it);
  }
  s += '\n';
  return s;
}

std::vector<nlohmann::ordered_json> readResultsJsonl(const std::string& path) {
  const std::string text = readAll(path);
  std::size_t good = 0;
  return parseRows(path, text.substr(0, wholeLinesLength(text)), good);
}

void writeResultsTable(const std::string& dir, const std::vector<nlohmann::ordered_json>& rows) {
  ensureDirectory(dir);
  std::string jsonl;
  std::string csv = csvHeader();
  for (const nlohmann::ordered_json& row : rows) {
    jsonl += row.dump() + "\n";
    csv += csvRow(row);
  }
  writeFileAtomically(dir + "/results.jsonl", jsonl);
  writeFileAtomically(dir + "/results.csv", csv);
}

ResultsTable::ResultsTable(const std::string& dir, double sync_interval_s)
    : jsonl_path_(dir + "/results.jsonl"),
      csv_path_(dir + "/results.csv"),
      sync_interval_s_(sync_interval_s) {
  ensureDirectory(dir);
  // results.jsonl: keep its whole, parsable rows.
  const std::string jsonl = readAll(jsonl_path_);
  std::size_t good = 0;
  const std::vector<nlohmann::ordered_json> rows =
      parseRows(jsonl_path_, jsonl.substr(0, wholeLinesLength(jsonl)), good);
  if (good != jsonl.size()) std::filesystem::resize_file(jsonl_path_, good);
  for (const nlohmann::ordered_json& row : rows) {
    done_[row["episode_id"].get<std::string>()] = row.value("met_tolerance", false);
  }

  // results.csv: the same ids under the same header, or rebuilt from results.jsonl.
  const std::string csv = readAll(csv_path_);
  const std::vector<std::string> csv_lines = lines(csv.substr(0, wholeLinesLength(csv)));
  if (!csv_lines.empty() && csv_lines.front() + "\n" != csvHeader()) {
    throw Error(csv_path_ +
                ":1: has other columns than this parksim writes (a table from another version?); "
                "use another --out directory");
  }
  std::multiset<std::string> csv_ids;
  for (std::size_t i = 1; i < csv_lines.size(); ++i) {
    csv_ids.insert(csv_lines[i].substr(0, csv_lines[i].find(',')));
  }
  std::multiset<std::string> jsonl_ids;
  for (const auto& [id, met] : done_) jsonl_ids.insert(id);
  if (csv_lines.empty() || csv_ids != jsonl_ids || rows.size() != done_.size()) {
    std::string text = csvHeader();
    for (const nlohmann::ordered_json& row : rows) text += csvRow(row);
    writeFileAtomically(csv_path_, text);
  }

  jsonl_fd_ = ::open(jsonl_path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (jsonl_fd_ < 0) throw Error(openError(jsonl_path_));
  csv_fd_ = ::open(csv_path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (csv_fd_ < 0) {
    ::close(jsonl_fd_);
    throw Error(openError(csv_path_));
  }
  last_sync_s_ = nowSeconds();
}

ResultsTable::~ResultsTable() {
  if (jsonl_fd_ >= 0) {
    ::fdatasync(jsonl_fd_);
    ::close(jsonl_fd_);
  }
  if (csv_fd_ >= 0) {
    ::fdatasync(csv_fd_);
    ::close(csv_fd_);
  }
}

void ResultsTable::append(const nlohmann::ordered_json& row) {
  const std::string id = row.at("episode_id").get<std::string>();
  writeAll(jsonl_fd_, jsonl_path_, row.dump() + "\n");
  writeAll(csv_fd_, csv_path_, csvRow(row));
  done_[id] = row.value("met_tolerance", false);
  if (nowSeconds() - last_sync_s_ >= sync_interval_s_) sync();
}

void ResultsTable::sync() {
  if (::fdatasync(jsonl_fd_) != 0) failErrno(jsonl_path_, "cannot sync");
  if (::fdatasync(csv_fd_) != 0) failErrno(csv_path_, "cannot sync");
  last_sync_s_ = nowSeconds();
}

}  // namespace parksim
