// `parksim run --realism ... --noise-seed ... --realisations ...` and the tolerance options,
// end to end.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;
using testing::runParksim;
using testing::slurp;

class RunRealism : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(parksim::testing::binaryDir()) / "test-output" / "sim-realism" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  static std::string world(const std::string& name) {
    return parksim::testing::sourceDir() + "/worlds/" + name + ".yaml";
  }
  std::string out(const std::string& sub) const { return (dir_ / sub).string(); }
  static std::string header(const std::string& csv) { return csv.substr(0, csv.find('\n')); }
  fs::path dir_;
};

TEST_F(RunRealism, LabRealisationsReportADistributionAndTheFilesOfTheFirst) {
  const CliRun r = runParksim("run " + world("head_in") +
                              " --realism lab --noise-seed 4 --realisations 3 --out " + out("lab"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("3 realisations (lab realism, noise seeds 4..6)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("max tracking error"), std::string::npos);
  const nlohmann::json m = nlohmann::json::parse(slurp(dir_ / "lab" / "metrics.json"));
  EXPECT_EQ(m["realism"], "lab");
  EXPECT_EQ(m["noise_seed"], 4);
  EXPECT_EQ(m["realisations.count"], 3);
  EXPECT_EQ(m["realisation.2.noise_seed"], 6);
  EXPECT_EQ(m["realisation.0.max_pos_err_m"], m["max_pos_err_m"]);
  EXPECT_LE(m["realisations.max_pos_err_m.median"].get<double>(),
            m["realisations.max_pos_err_m.max"].get<double>());
  for (const auto& [key, value] : m.items()) {
    if (key != "contact_bodies") {
      EXPECT_FALSE(value.is_structured()) << key;
    }
  }
  EXPECT_EQ(header(slurp(dir_ / "lab" / "executed.csv")),
            "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,"
            "omega_right,pos_err,heading_err,x_est,y_est,theta_est,est_pos_err,est_heading_err,"
            "effort_left,effort_right,torque_left,torque_right,slip_left,slip_right,"
            "encoder_left,encoder_right");
  EXPECT_EQ(header(slurp(dir_ / "lab" / "sensors.csv")), "t_received,t_taken,x,y,theta");
}

TEST_F(RunRealism, IdealWritesTodaysColumnsAndNoSensorFile) {
  const CliRun r = runParksim("run " + world("parallel") + " --realism ideal --out " + out("i"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(header(slurp(dir_ / "i" / "executed.csv")),
            "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,"
            "omega_right,pos_err,heading_err");
  EXPECT_FALSE(fs::exists(dir_ / "i" / "sensors.csv"));
}

TEST_F(RunRealism, TheToleranceComesFromTheCommandLineOrTheWorld) {
  // lab tracks to a few millimetres: a 1 mm tolerance fails, exit 4 with the reason.
  const CliRun tight = runParksim("run " + world("head_in") +
                                  " --realism lab --max-tracking-error-mm 1 --out " + out("t"));
  EXPECT_EQ(tight.exit_code, 4) << tight.out;
  EXPECT_NE(tight.out.find("tracking tolerance not met: max_pos_err_m"), std::string::npos)
      << tight.out;
  // The same from a world file's tolerance: section, and a realism: section used by default.
  std::string text = slurp(world("head_in"));
  text += "realism: {preset: lab, control: {rate_hz: 30}}\ntolerance: {max_pos_err_m: 0.001}\n";
  const std::string path = out("w.yaml");
  std::ofstream(path) << text;
  const CliRun from_world = runParksim("run " + path + " --out " + out("w"));
  EXPECT_EQ(from_world.exit_code, 4) << from_world.out;
  const nlohmann::json m = nlohmann::json::parse(slurp(dir_ / "w" / "metrics.json"));
  EXPECT_EQ(m["realism"], "lab+world");
  EXPECT_EQ(m["tolerance.max_pos_err_m"], 0.001);
  // A command-line tolerance wins over the world's.
  const CliRun loose = runParksim("run " + path + " --max-tracking-error-mm 30 --out " + out("l"));
  EXPECT_EQ(loose.exit_code, 0) << loose.out;
}

TEST_F(RunRealism, BadRealismInputIsRefusedWithExitTwo) {
  EXPECT_EQ(runParksim("run " + world("head_in") + " --realism lab3").exit_code, 2);
  EXPECT_EQ(runParksim("run " + world("head_in") + " --realisations 0").exit_code, 2);
  EXPECT_EQ(runParksim("run " + world("head_in") + " --noise-seed -1").exit_code, 2);
  std::string text = slurp(world("head_in"));
  text += "realism:\n  pose_sensor: {rate_hz: -5}\n";
  const std::string path = out("bad.yaml");
  std::ofstream(path) << text;
  const CliRun r = runParksim("run " + path + " --out " + out("bad"));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("realism.pose_sensor.rate_hz: must be positive"), std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "bad"));
}

}  // namespace
}  // namespace parksim
