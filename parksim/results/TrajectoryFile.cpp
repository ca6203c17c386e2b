#include "parksim/results/TrajectoryFile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/DiffDrive.h"
#include "parksim/core/Error.h"
#include "parksim/core/InputFile.h"
#include "parksim/core/NumberFormat.h"

namespace parksim {

void writeTrajectoryCsv(const std::string& path, const Trajectory& traj, const RobotDef& robot) {
  std::string out = "t,x,y,theta,omega_left,omega_right,v,omega\n";
  out.reserve(out.size() + traj.points.size() * 160);
  for (const TrajectoryPoint& p : traj.points) {
    const Twist tw = toTwist(p.wheels, robot);
    const double values[] = {
        p.t_s,    p.pose.x,      p.pose.y, p.pose.theta, p.wheels.left_radps, p.wheels.right_radps,
        tw.v_mps, tw.omega_radps};
    for (std::size_t i = 0; i < std::size(values); ++i) {
      if (i > 0) out += ',';
      appendRoundTrip(out, values[i]);
    }
    out += '\n';
  }
  writeFileAtomically(path, out);
}

namespace {

// The next line of `text` from `pos` (without its '\n' or "\r\n"); advances `pos`.
std::string_view nextLine(std::string_view text, std::size_t& pos) {
  const std::size_t end = std::min(text.find('\n', pos), text.size());
  std::string_view line = text.substr(pos, end - pos);
  pos = end + 1;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

void splitCells(std::string_view line, std::vector<std::string_view>& cells) {
  cells.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

std::string limitText(double value) { return formatGeneral(value); }

}  // namespace

Trajectory parseTrajectoryCsv(std::string_view text, const std::string& path) {
  using L = PlanFileLimits;
  std::size_t pos = 0;
  int line_no = 0;
  auto at = [&](int line) { return path + ":" + std::to_string(line) + ": "; };
  auto next = [&](std::string_view& line) {
    if (pos >= text.size()) return false;
    line = nextLine(text, pos);
    ++line_no;
    if (line.size() > L::kMaxLineBytes) {
      throw Error(at(line_no) + "line is " + std::to_string(line.size()) +
                  " bytes, more than the limit of " + std::to_string(L::kMaxLineBytes) +
                  " (docs/limits.md)");
    }
    return true;
  };
  // A byte-order mark (spreadsheets' "CSV UTF-8") is no part of the first column's name.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
  std::string_view line;
  if (!next(line)) throw Error(path + ":1: empty trajectory file (expected a header)");
  std::vector<std::string_view> cells;
  splitCells(line, cells);
  const std::size_t columns = cells.size();
  std::map<std::string_view, std::size_t> column;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!column.emplace(cells[i], i).second) {
      const std::string shown(cells[i].substr(0, 40));
      throw Error(path + ":1: header names column '" + shown + "' twice");
    }
  }
  const char* required[] = {"t", "x", "y", "theta", "omega_left", "omega_right"};
  std::size_t index[6];
  for (int k = 0; k < 6; ++k) {
    const auto it = column.find(required[k]);
    if (it == column.end()) {
      throw Error(path + ":1: header lacks column '" + required[k] + "'");
    }
    index[k] = it->second;
  }
  Trajectory traj;
  while (next(line)) {
    if (line.empty()) continue;
    if (traj.points.size() >= L::kMaxRows) {
      throw Error(at(line_no) + "more than the limit of " + std::to_string(L::kMaxRows) +
                  " rows (docs/limits.md)");
    }
    splitCells(line, cells);
    // A row of another width is a shifted or truncated file, not a row to guess at.
    if (cells.size() != columns) {
      throw Error(at(line_no) + "row has " + std::to_string(cells.size()) +
                  " cells, the header has " + std::to_string(columns) + " columns");
    }
    double v[6];
    for (int k = 0; k < 6; ++k) {
      const std::string where = at(line_no) + "column '" + required[k] + "'";
      if (index[k] >= cells.size()) throw Error(where + ": missing value");
      const std::string_view cell = cells[index[k]];
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v[k]);
      if (ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(v[k])) {
        const std::string shown(cell.substr(0, 40));
        throw Error(where + ": '" + shown + (cell.size() > 40 ? "...'" : "'") +
                    " is not a finite number");
      }
      if (k == 0 && !(v[k] >= 0.0 && v[k] <= L::kMaxTimeS)) {
        throw Error(where + ": must be in [0, " + limitText(L::kMaxTimeS) + "] s, got " +
                    limitText(v[k]) + " (docs/limits.md)");
      }
      if (k > 0 && !(std::abs(v[k]) <= L::kMaxMagnitude)) {
        throw Error(where + ": must be within +-" + limitText(L::kMaxMagnitude) + ", got " +
                    limitText(v[k]) + " (docs/limits.md)");
      }
    }
    TrajectoryPoint p;
    p.t_s = v[0];
    p.pose = {v[1], v[2], v[3]};
    p.wheels = {v[4], v[5]};
    if (!traj.points.empty()) {
      const double gap = p.t_s - traj.points.back().t_s;
      if (!(gap > 0.0)) throw Error(at(line_no) + "column 't': time does not increase");
      if (gap > L::kMaxGapS) {
        throw Error(at(line_no) + "column 't': " + limitText(gap) +
                    " s after the previous row, more than the limit of " + limitText(L::kMaxGapS) +
                    " s (docs/limits.md)");
      }
    }
    traj.points.push_back(p);
  }
  if (traj.points.empty()) throw Error(path + ": trajectory has no rows");
  return traj;
}

Trajectory readTrajectoryCsv(const std::string& path) {
  return parseTrajectoryCsv(readInputFile(path, PlanFileLimits::kMaxBytes, "plan file"), path);
}

}  // namespace parksim
