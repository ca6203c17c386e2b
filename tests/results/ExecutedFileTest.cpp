// executed.csv's header and its exact numbers.

#include "parksim/results/ExecutedFile.h"

#include <sstream>

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(ExecutedFile, ExecutedCsvHeaderAndRoundTripPrecision) {
  ExecutedRow row;
  row.t_s = 1.0 / 240.0;
  row.pose = {0.1, 1.0 / 3.0, -2.0 / 7.0};
  row.pos_err_m = 1e-17;
  const std::string csv = executedCsv({row});
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header,
            "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,"
            "omega_right,pos_err,heading_err");
  std::istringstream cells(line);
  std::string cell;
  std::vector<double> values;
  while (std::getline(cells, cell, ',')) values.push_back(std::stod(cell));
  ASSERT_EQ(values.size(), 13u);
  EXPECT_EQ(values[0], row.t_s);
  EXPECT_EQ(values[2], row.pose.y);
  EXPECT_EQ(values[3], row.pose.theta);
  EXPECT_EQ(values[11], row.pos_err_m);
}

}  // namespace
}  // namespace parksim
