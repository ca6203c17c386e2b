#include "parksim/renders/plots/TrackingPlot.h"

#include <gtest/gtest.h>

#include <fstream>

#include "RenderTestUtil.h"
#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

TEST(TrackingPlotTest, NiceTicksAreRoundAndCoverTheRange) {
  EXPECT_EQ(niceTicks(0.0, 10.0, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  const std::vector<double> t = niceTicks(-0.37, 1.21, 8);
  ASSERT_FALSE(t.empty());
  EXPECT_NEAR(t[1] - t[0], 0.2, 1e-12);
  EXPECT_GE(t.front(), -0.37);
  EXPECT_LE(t.back(), 1.21);
  EXPECT_EQ(t[1], 0.0);  // exactly zero, not 1e-17
  EXPECT_TRUE(niceTicks(1.0, 1.0, 5).empty());
}

TEST(TrackingPlotTest, ReadsColumnsByName) {
  const std::string path = rendertest::outputDir("TrackingPlotTest") + "/executed.csv";
  std::ofstream(path) << "t,x,y,theta,pos_err,heading_err\n"
                         "0,0,0,0,0,0\n"
                         "0.5,0.1,0,0,0.002,-0.01\n"
                         "\n"
                         "1.0,0.2,0,0,0.001,0.02\n";
  const TrackingSeries s = readTrackingCsv(path);
  EXPECT_EQ(s.t_s, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(s.position_error_m, (std::vector<double>{0.0, 0.002, 0.001}));
  EXPECT_EQ(s.heading_error_rad, (std::vector<double>{0.0, -0.01, 0.02}));

  std::ofstream(path) << "t_s,position_error_m,heading_error_deg\n1,0.5,90\n";
  const TrackingSeries d = readTrackingCsv(path);
  EXPECT_NEAR(d.heading_error_rad.at(0), kPi / 2, 1e-15);

  std::ofstream(path) << "t,pos_err\n1,2\n";
  EXPECT_THROW(readTrackingCsv(path), Error);
  std::ofstream(path) << "t,pos_err,heading_err\n1,abc,0\n";
  try {
    readTrackingCsv(path);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(":2: column 'pos_err': 'abc' is not a finite number"),
              std::string::npos)
        << e.what();
  }
  // Found by the hostile pass: a header alone and time running backwards were drawn silently.
  const auto message = [&path](const std::string& text) {
    std::ofstream(path) << text;
    try {
      readTrackingCsv(path);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("t,pos_err,heading_err\n"), path + ": no rows (the header alone)");
  EXPECT_EQ(message("t,pos_err,heading_err\n1,0,0\n0.5,0,0\n"),
            path + ":3: column 't': time does not increase");
}

TEST(TrackingPlotTest, PlotHasTwoPanelsWithDataAxesAndLabels) {
  TrackingSeries s;
  for (int i = 0; i <= 100; ++i) {
    s.t_s.push_back(0.05 * i);
    s.position_error_m.push_back(0.001 * std::sin(0.1 * i) * std::sin(0.1 * i));
    s.heading_error_rad.push_back(0.02 * std::cos(0.2 * i));
  }
  const SceneStyle style;
  const Scene scene = buildTrackingPlot(s, "title", 800, 600, style);
  EXPECT_DOUBLE_EQ(scene.extent.width(), 800.0);
  int data_lines = 0;
  for (const ScenePolyline& l : scene.lines) data_lines += l.points.size() == 101;
  EXPECT_EQ(data_lines, 2);
  auto has = [&](const std::string& text) {
    for (const SceneText& t : scene.texts) {
      if (t.text == text) return true;
    }
    return false;
  };
  EXPECT_TRUE(has("title"));
  EXPECT_TRUE(has("time (s)"));
  EXPECT_TRUE(has("position error (mm)"));
  EXPECT_TRUE(has("heading error (\u00b0)"));
  EXPECT_TRUE(has("5"));  // last time tick
  // Every point of the data lies inside the image.
  for (const ScenePolyline& l : scene.lines) {
    for (const Eigen::Vector3d& p : l.points) {
      EXPECT_GE(p.x(), 0.0);
      EXPECT_LE(p.x(), 800.0);
      EXPECT_GE(p.y(), 0.0);
      EXPECT_LE(p.y(), 600.0);
    }
  }
  s.t_s.pop_back();
  EXPECT_THROW(buildTrackingPlot(s, "", 800, 600, style), Error);
}

}  // namespace
}  // namespace parksim
