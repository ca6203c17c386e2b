#include "parksim/results/episode/TrajectoryFile.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/SampleTrajectory.h"

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace trajectory_file_test {

std::string tempPath(const std::string& name) {
  const std::filesystem::path dir = parksim::testing::testOutputDir("results");
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

Trajectory sample() { return testing::sampleTrajectory(); }

TEST(TrajectoryFile, CsvRoundTripIsExact) {
  const Trajectory t = sample();
  const std::string path = tempPath("roundtrip.csv");
  writeTrajectoryCsv(path, t, RobotDef{});
  EXPECT_EQ(readTrajectoryCsv(path), t);
  std::remove(path.c_str());
}

TEST(TrajectoryFile, ReaderNamesFileLineAndColumn) {
  const std::string path = tempPath("bad.csv");
  {
    std::ofstream out(path);
    out << "t,x,y,theta,omega_left,omega_right\n0,0,0,0,1,1\n0.1,0,zz,0,1,1\n";
  }
  try {
    readTrajectoryCsv(path);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path + ":3: column 'y': 'zz' is not a finite number");
  }
  std::remove(path.c_str());
}

TEST(TrajectoryFile, ReaderRefusesWhatItsLimitsExclude) {
  const std::string h = "t,x,y,theta,omega_left,omega_right\n";
  auto message = [](const std::string& text) {
    try {
      parseTrajectoryCsv(text, "p.csv");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(h + "0,0,0,0,0,0\n0.1,0,0,0,0,0\n"), "accepted");
  EXPECT_NE(message(h + "1e300,0,0,0,0,0\n").find("p.csv:2: column 't': must be in [0, 3600]"),
            std::string::npos);
  EXPECT_NE(message(h + "-1,0,0,0,0,0\n").find("must be in [0, 3600]"), std::string::npos);
  EXPECT_NE(message(h + "0,0,0,0,0,0\n61,0,0,0,0,0\n").find("more than the limit of 60 s"),
            std::string::npos);
  EXPECT_NE(message(h + "0,0,0,0,1e7,0\n").find("column 'omega_left': must be within"),
            std::string::npos);
  EXPECT_NE(message(h + std::string(5000, ',') + "\n").find("p.csv:2: line is 5000 bytes"),
            std::string::npos);
  EXPECT_NE(message(std::string(5000, ',')).find("p.csv:1: line is 5000 bytes"), std::string::npos);
}

// Found by the hostile pass: a spreadsheet's byte-order mark made the header "lack column 't'";
// a column named twice and rows of another width than the header were read silently.
TEST(TrajectoryFile, ReaderTakesAByteOrderMarkAndRefusesRaggedTables) {
  const std::string h = "t,x,y,theta,omega_left,omega_right\n";
  auto message = [](const std::string& text) {
    try {
      parseTrajectoryCsv(text, "p.csv");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("\xEF\xBB\xBF" + h + "0,0,0,0,0,0\n"), "accepted");
  EXPECT_EQ(message("t,x,y,theta,omega_left,omega_right,t\n0,0,0,0,0,0,0\n"),
            "p.csv:1: header names column 't' twice");
  EXPECT_EQ(message(h + "0,0,0,0,0,0\n0.1,0,0,0,0\n"),
            "p.csv:3: row has 5 cells, the header has 6 columns");
  EXPECT_EQ(message(h + "0,0,0,0,0,0,7\n"), "p.csv:2: row has 7 cells, the header has 6 columns");
}

// Issue 22: a plan in a 20 km lot could last longer than the reader's 3600 s, so `run --plan`
// could not read back what `plan` wrote. The writer now refuses what the reader would.
TEST(TrajectoryFile, TheWriterRefusesAPlanItsReaderCouldNotReadBack) {
  Trajectory t;
  for (int i = 0; i <= 80; ++i) t.points.push_back({50.0 * i, Pose2{0.0, 0.0, 0.0}, {}});
  ASSERT_GT(t.duration(), PlanFileLimits::kMaxTimeS);
  const std::string path = tempPath("long.csv");
  std::remove(path.c_str());
  ASSERT_TRUE(planFileProblem(t).has_value());
  try {
    writeTrajectoryCsv(path, t, RobotDef{});
    FAIL() << "a 4000 s plan was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the plan exceeds the limits of a plan file (row 74: t "
                                         "= 3650 s, outside [0, 3600] s"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));  // nothing half-written
  // Within the limits, what is written reads back.
  t.points.resize(73);  // 0 to 3600 s
  EXPECT_FALSE(planFileProblem(t).has_value());
  writeTrajectoryCsv(path, t, RobotDef{});
  EXPECT_EQ(readTrajectoryCsv(path).points.size(), 73u);
  std::remove(path.c_str());
}

// Issue 22: a NUL byte in a cell cut the message short; it shows as \x00 as docs/limits.md says.
TEST(TrajectoryFile, ControlBytesInACellAreEscapedInTheMessage) {
  const std::string text =
      std::string("t,x,y,theta,omega_left,omega_right\n0,0,") + '\0' + "1\x01,0,0,0\n";
  try {
    parseTrajectoryCsv(text, "p.csv");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "p.csv:2: column 'y': '\\x001\x01' is not a finite number");
  }
}

// Issue 22: `render --executed` checked less than the plan reader; it now has the same limits
// on the columns it plots.
TEST(TrajectoryFile, TimeSeriesGetThePlanReadersChecks) {
  const std::string path = tempPath("executed.csv");
  const std::vector<std::vector<std::string_view>> columns = {
      {"t", "t_s"}, {"pos_err", "pos_err_m"}, {"heading_err", "heading_err_rad"}};
  auto message = [&](const std::string& text) {
    {
      std::ofstream out(path, std::ios::binary);
      out << text;
    }
    try {
      checkTimeSeriesCsv(path, columns);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("t,pos_err_m,other\n0,0.001,x\n0.1,0.002,y\n"), "accepted");
  EXPECT_EQ(message("t,pos_err_m\n0,0\n0,0\n"), path + ":3: column 't': time does not increase");
  EXPECT_EQ(message("t,pos_err_m\n0,nan\n"),
            path + ":2: column 'pos_err_m': 'nan' is not a finite number");
  EXPECT_EQ(message("t,pos_err_m\n0,0\n1,0,3\n"),
            path + ":3: row has 3 cells, the header has 2 columns");
  EXPECT_NE(message("t,pos_err_m\n0,1e300\n").find("must be within +-1e+06"), std::string::npos);
  EXPECT_NE(message("t,pos_err_m\n1e9,0\n").find("column 't': must be in [0, 3660] s"),
            std::string::npos);
  EXPECT_EQ(message("t,t\n0,0\n"), path + ":1: header names column 't' twice");
  std::remove(path.c_str());
}

TEST(TrajectoryFile, OnlyRegularFilesAreRead) {
  EXPECT_THROW(readTrajectoryCsv("/dev/zero"), Error);
  EXPECT_THROW(readTrajectoryCsv(std::filesystem::temp_directory_path().string()), Error);
  EXPECT_THROW(readInputFile("/dev/urandom", 100, "plan file"), Error);
  const std::string path = tempPath("input_file_test.csv");
  std::ofstream(path) << std::string(101, 'x');
  EXPECT_THROW(readInputFile(path, 100, "plan file"), Error);
  EXPECT_EQ(readInputFile(path, 101, "plan file").size(), 101u);
  std::filesystem::remove(path);
}

}  // namespace trajectory_file_test
}  // namespace parksim
