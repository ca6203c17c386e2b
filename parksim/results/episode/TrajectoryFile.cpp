#include "parksim/results/episode/TrajectoryFile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

namespace {

// A car's rows: the speed and steering angle it drives by, the curvature and gear they make.
std::string carCsv(const Trajectory& traj, const RobotDef& car) {
  std::string out = "t,x,y,theta,v,steer_rad,curvature,gear\n";
  out.reserve(out.size() + traj.points.size() * 140);
  for (const TrajectoryPoint& p : traj.points) {
    const double v = toTwist(p.wheels, car).v_mps;
    const double still = kCarStillFraction * car.max_speed_mps;
    const double gear = v > still ? 1.0 : (v < -still ? -1.0 : 0.0);
    const double values[] = {p.t_s,
                             p.pose.x,
                             p.pose.y,
                             p.pose.theta,
                             v,
                             p.steer_rad,
                             std::tan(p.steer_rad) / car.axle_distance_m,
                             gear};
    for (std::size_t i = 0; i < std::size(values); ++i) {
      if (i > 0) out += ',';
      appendRoundTrip(out, values[i]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace

void writeTrajectoryCsv(const std::string& path, const Trajectory& traj, const RobotDef& robot) {
  // What `run --plan` could not read back is not written: the reader's limits are the writer's.
  if (const std::optional<std::string> problem = planFileProblem(traj)) {
    throw Error(path + ": the plan exceeds the limits of a plan file (" + *problem +
                "; docs/limits.md), so `run --plan` could not read it back");
  }
  if (robot.isCar()) {
    writeFileAtomically(path, carCsv(traj, robot));
    return;
  }
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

// A cell shown in a message: at most 40 bytes. A NUL byte in a cell cut the message short (it
// ends the C string main() prints); it shows as \x00. Other control bytes are escaped where
// the message is printed (cli::printable), as in every other message.
std::string shownCell(std::string_view cell) {
  std::string shown;
  for (const char c : cell.substr(0, 40)) {
    if (c == '\0') {
      shown += "\\x00";
    } else {
      shown += c;
    }
  }
  return shown + (cell.size() > 40 ? "..." : "");
}

// A time series in CSV with the plan file's limits (PlanFileLimits): one line at a time, cells
// as views into it. `columns` lists, per column read, the names it may have; the first is the
// time. A column not found is an error when `required`, else it is not read (NaN). Calls
// `on_row` with the values of each data row, in the order of `columns`.
void scanSeries(std::string_view text, const std::string& path, const char* what, double max_time_s,
                const std::vector<std::vector<std::string_view>>& columns, bool required,
                const std::function<void(const std::vector<double>&, int line)>& on_row) {
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
  if (!next(line)) throw Error(path + ":1: empty " + what + " (expected a header)");
  std::vector<std::string_view> cells;
  splitCells(line, cells);
  const std::size_t width = cells.size();
  std::map<std::string_view, std::size_t> column;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!column.emplace(cells[i], i).second) {
      throw Error(path + ":1: header names column '" + shownCell(cells[i]) + "' twice");
    }
  }
  std::vector<std::size_t> index(columns.size(), width);  // width: not in the file
  std::vector<std::string> names(columns.size());
  for (std::size_t k = 0; k < columns.size(); ++k) {
    for (const std::string_view name : columns[k]) {
      const auto it = column.find(name);
      if (it == column.end()) continue;
      index[k] = it->second;
      names[k] = std::string(name);
      break;
    }
    if (index[k] == width && required) {
      throw Error(path + ":1: header lacks column '" + std::string(columns[k].front()) + "'");
    }
  }
  std::vector<double> v(columns.size());
  std::size_t rows = 0;
  double last_t = 0.0;
  while (next(line)) {
    if (line.empty()) continue;
    if (rows >= L::kMaxRows) {
      throw Error(at(line_no) + "more than the limit of " + std::to_string(L::kMaxRows) +
                  " rows (docs/limits.md)");
    }
    splitCells(line, cells);
    // A row of another width is a shifted or truncated file, not a row to guess at.
    if (cells.size() != width) {
      throw Error(at(line_no) + "row has " + std::to_string(cells.size()) +
                  " cells, the header has " + std::to_string(width) + " columns");
    }
    for (std::size_t k = 0; k < columns.size(); ++k) {
      v[k] = std::numeric_limits<double>::quiet_NaN();
      if (index[k] == width) continue;
      const std::string where = at(line_no) + "column '" + names[k] + "'";
      const std::string_view cell = cells[index[k]];
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v[k]);
      if (ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(v[k])) {
        throw Error(where + ": '" + shownCell(cell) + "' is not a finite number");
      }
      if (k == 0 && !(v[k] >= 0.0 && v[k] <= max_time_s)) {
        throw Error(where + ": must be in [0, " + limitText(max_time_s) + "] s, got " +
                    limitText(v[k]) + " (docs/limits.md)");
      }
      if (k > 0 && !(std::abs(v[k]) <= L::kMaxMagnitude)) {
        throw Error(where + ": must be within +-" + limitText(L::kMaxMagnitude) + ", got " +
                    limitText(v[k]) + " (docs/limits.md)");
      }
    }
    if (rows > 0 && index[0] != width) {
      const double gap = v[0] - last_t;
      if (!(gap > 0.0)) {
        throw Error(at(line_no) + "column '" + names[0] + "': time does not increase");
      }
      if (gap > L::kMaxGapS) {
        throw Error(at(line_no) + "column '" + names[0] + "': " + limitText(gap) +
                    " s after the previous row, more than the limit of " + limitText(L::kMaxGapS) +
                    " s (docs/limits.md)");
      }
    }
    last_t = v[0];
    ++rows;
    on_row(v, line_no);
  }
}

}  // namespace

std::optional<std::string> planFileProblem(const Trajectory& traj) {
  using L = PlanFileLimits;
  if (traj.points.size() > L::kMaxRows) {
    return std::to_string(traj.points.size()) + " rows, more than the limit of " +
           std::to_string(L::kMaxRows);
  }
  for (std::size_t i = 0; i < traj.points.size(); ++i) {
    const TrajectoryPoint& p = traj.points[i];
    const std::string row = "row " + std::to_string(i + 1) + ": ";
    if (!(p.t_s >= 0.0 && p.t_s <= L::kMaxTimeS)) {
      return row + "t = " + limitText(p.t_s) + " s, outside [0, " + limitText(L::kMaxTimeS) +
             "] s (a plan " + limitText(traj.duration()) + " s long)";
    }
    if (i > 0) {
      const double gap = p.t_s - traj.points[i - 1].t_s;
      if (!(gap > 0.0 && gap <= L::kMaxGapS)) {
        return row + limitText(gap) + " s after the previous row, outside (0, " +
               limitText(L::kMaxGapS) + "] s";
      }
    }
    for (const double value :
         {p.pose.x, p.pose.y, p.pose.theta, p.wheels.left_radps, p.wheels.right_radps}) {
      if (!(std::abs(value) <= L::kMaxMagnitude)) {
        return row + "a value of " + limitText(value) + ", beyond +-" + limitText(L::kMaxMagnitude);
      }
    }
  }
  return std::nullopt;
}

Trajectory parseTrajectoryCsvRows(std::string_view text, const std::string& path,
                                  const RobotDef& robot) {
  Trajectory traj;
  if (robot.isCar()) {
    // A car drives by its speed and steering angle; its rear wheels' speeds follow.
    scanSeries(
        text, path, "trajectory file", PlanFileLimits::kMaxTimeS,
        {{"t"}, {"x"}, {"y"}, {"theta"}, {"v"}, {"steer_rad"}}, true,
        [&traj, &robot, &path](const std::vector<double>& v, int line) {
          if (!(std::abs(v[5]) < 0.5 * kPi)) {
            throw Error(path + ":" + std::to_string(line) +
                        ": column 'steer_rad': must be within +-pi/2 rad (a front wheel "
                        "turned across the car has no curvature), got " +
                        limitText(v[5]));
          }
          TrajectoryPoint p;
          p.t_s = v[0];
          p.pose = {v[1], v[2], v[3]};
          p.wheels = toWheelSpeeds({v[4], v[4] * std::tan(v[5]) / robot.axle_distance_m}, robot);
          p.steer_rad = v[5];
          traj.points.push_back(p);
        });
    return traj;
  }
  scanSeries(text, path, "trajectory file", PlanFileLimits::kMaxTimeS,
             {{"t"}, {"x"}, {"y"}, {"theta"}, {"omega_left"}, {"omega_right"}}, true,
             [&traj](const std::vector<double>& v, int) {
               TrajectoryPoint p;
               p.t_s = v[0];
               p.pose = {v[1], v[2], v[3]};
               p.wheels = {v[4], v[5]};
               traj.points.push_back(p);
             });
  return traj;
}

Trajectory parseTrajectoryCsv(std::string_view text, const std::string& path,
                              const RobotDef& robot) {
  Trajectory traj = parseTrajectoryCsvRows(text, path, robot);
  if (traj.points.empty()) throw Error(path + ": trajectory has no rows");
  return traj;
}

void checkTimeSeriesCsv(const std::string& path,
                        const std::vector<std::vector<std::string_view>>& columns) {
  // An episode lasts its plan and a stop phase: a plan file's longest plan and one gap more.
  const double max_time_s = PlanFileLimits::kMaxTimeS + PlanFileLimits::kMaxGapS;
  scanSeries(readInputFile(path, kMaxSeriesFileBytes, "CSV file"), path, "CSV file", max_time_s,
             columns, false, [](const std::vector<double>&, int) {});
}

Trajectory readTrajectoryCsv(const std::string& path, const RobotDef& robot) {
  return parseTrajectoryCsv(readInputFile(path, PlanFileLimits::kMaxBytes, "plan file"), path,
                            robot);
}

}  // namespace parksim
