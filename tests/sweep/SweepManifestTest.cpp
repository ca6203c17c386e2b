// DIR/sweep.json (parksim/sweep/shards/SweepManifest.h): what a Slurm sweep asked of each task is
// written and read back, so that `--slurm --missing` asks for the same; a changed request of
// the wrong type or out of range is refused as not a manifest.

#include "parksim/sweep/shards/SweepManifest.h"

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "parksim/core/io/Error.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

SweepManifest slurmManifest() {
  SweepManifest m{"spec.yaml", "test", Shard{}, {"a", "b"}, 2};
  SlurmDef asked;
  asked.cpus_per_task = 3;
  asked.mem = "200M";
  asked.time = "00:10:00";
  asked.partition = "short";
  asked.account = "lab";
  asked.max_parallel = "%4";
  m.slurm_request = asked;
  return m;
}

TEST(SweepManifest, TheSlurmRequestIsReadBackAsWritten) {
  const std::string dir = testing::scratchDir();
  writeSweepManifest(dir, slurmManifest());
  SweepManifest back;
  ASSERT_TRUE(readSweepManifest(dir, back));
  EXPECT_EQ(back.slurm_shards, 2);
  ASSERT_TRUE(back.slurm_request.has_value());
  EXPECT_EQ(back.slurm_request->cpus_per_task, 3);
  EXPECT_EQ(back.slurm_request->mem, "200M");
  EXPECT_EQ(back.slurm_request->time, "00:10:00");
  EXPECT_EQ(back.slurm_request->partition, "short");
  EXPECT_EQ(back.slurm_request->account, "lab");
  EXPECT_EQ(back.slurm_request->max_parallel, "%4");
  // Only the request is recorded: paths and the job name are the command's of the day.
  EXPECT_EQ(back.slurm_request->parksim_exe, "");
}

TEST(SweepManifest, WithoutASlurmScriptThereIsNoRequest) {
  const std::string dir = testing::scratchDir();
  writeSweepManifest(dir, SweepManifest{"spec.yaml", "test", Shard{0, 2}, {"a"}});
  SweepManifest back;
  ASSERT_TRUE(readSweepManifest(dir, back));
  EXPECT_FALSE(back.slurm_request.has_value());
}

TEST(SweepManifest, AChangedRequestOfTheWrongTypeIsNotAManifest) {
  const std::string dir = testing::scratchDir();
  writeSweepManifest(dir, slurmManifest());
  std::stringstream text;
  text << std::ifstream(dir + "/sweep.json").rdbuf();
  const nlohmann::json good = nlohmann::json::parse(text.str());
  const auto refused = [&](const char* key, const nlohmann::json& value) {
    nlohmann::json j = good;
    if (key == nullptr) {
      j["slurm_request"] = value;
    } else {
      j["slurm_request"][key] = value;
    }
    try {
      parseSweepManifest(j.dump(), "sweep.json");
    } catch (const Error& e) {
      return std::string(e.what()) ==
             "sweep.json: not a sweep manifest (format parksim-sweep-manifest/2)";
    }
    return false;
  };
  EXPECT_TRUE(refused(nullptr, "1G"));
  EXPECT_TRUE(refused("cpus_per_task", 0));
  EXPECT_TRUE(refused("cpus_per_task", 1025));
  EXPECT_TRUE(refused("cpus_per_task", "2"));
  EXPECT_TRUE(refused("mem", 200));
  EXPECT_TRUE(refused("time", nullptr));
  nlohmann::json without_account = good;
  without_account["slurm_request"].erase("account");
  EXPECT_THROW(parseSweepManifest(without_account.dump(), "sweep.json"), Error);
  // The unchanged text is accepted (the refusals above are the changes').
  EXPECT_NO_THROW(parseSweepManifest(good.dump(), "sweep.json"));
}

}  // namespace
}  // namespace parksim
