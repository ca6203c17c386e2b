#include "parksim/results/TrajectoryFile.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/support/SampleTrajectory.h"

#include "parksim/core/Error.h"
#include "parksim/core/InputFile.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

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

}  // namespace
}  // namespace parksim
