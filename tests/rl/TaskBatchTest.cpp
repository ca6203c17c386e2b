// The batch: the same trajectories with 1 and 2 threads, task i as a lone task seeded s + i,
// autoreset at the next step or within the same step, refused actions.

#include "parksim/rl/TaskBatch.h"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

// Random actions (seeded), the same for every run.
std::vector<std::vector<TaskAction>> actions(std::size_t n, int steps) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::vector<TaskAction>> out(static_cast<std::size_t>(steps));
  for (auto& row : out) {
    for (std::size_t i = 0; i < n; ++i) row.push_back({u(rng), u(rng)});
  }
  return out;
}

std::vector<std::vector<TaskStep>> rollout(const ParkingTaskDef& def, int threads,
                                           const std::vector<std::vector<TaskAction>>& a) {
  TaskBatchDef batch_def;
  batch_def.threads = threads;
  TaskBatch batch(testing::studyLot(), def, a.front().size(), batch_def);
  EXPECT_EQ(batch.threads(), threads);
  std::vector<std::optional<std::uint64_t>> seeds;
  for (std::size_t i = 0; i < batch.size(); ++i) seeds.emplace_back(100 + i);
  std::vector<std::vector<TaskStep>> out{batch.reset(seeds)};
  for (const auto& row : a) out.push_back(batch.step(row));
  return out;
}

void expectSame(const TaskStep& x, const TaskStep& y) {
  EXPECT_EQ(x.observation, y.observation);
  EXPECT_EQ(x.reward, y.reward);
  EXPECT_EQ(x.terminated, y.terminated);
  EXPECT_EQ(x.truncated, y.truncated);
  EXPECT_EQ(x.info.pose, y.info.pose);
  EXPECT_EQ(x.info.contacts, y.info.contacts);
}

TEST(TaskBatch, OneAndTwoThreadsGiveIdenticalTrajectories) {
  for (TaskFidelity fidelity : {TaskFidelity::kDynamics, TaskFidelity::kKinematic}) {
    ParkingTaskDef def;
    def.fidelity = fidelity;
    def.max_episode_steps = 15;  // several autoresets within the run
    const auto a = actions(4, 40);
    const auto one = rollout(def, 1, a);
    const auto two = rollout(def, 2, a);
    int ends = 0;
    for (std::size_t k = 0; k < one.size(); ++k) {
      for (std::size_t i = 0; i < one[k].size(); ++i) {
        SCOPED_TRACE(std::string(toString(fidelity)) + " step " + std::to_string(k));
        expectSame(one[k][i], two[k][i]);
        ends += one[k][i].terminated || one[k][i].truncated;
      }
    }
    EXPECT_GE(ends, 8) << toString(fidelity);
  }
}

TEST(TaskBatch, TaskIIsALoneTaskSeededWithItsSeedAndResetAfterEachEnd) {
  ParkingTaskDef def;
  def.fidelity = TaskFidelity::kKinematic;
  def.max_episode_steps = 5;
  const auto a = actions(3, 20);
  const auto batch = rollout(def, 2, a);
  for (std::size_t i = 0; i < 3; ++i) {
    ParkingTask lone(testing::studyLot(), def);
    lone.seed(100 + i);
    expectSame(batch[0][i], lone.reset());
    for (std::size_t k = 0; k < a.size(); ++k) {
      SCOPED_TRACE("task " + std::to_string(i) + " step " + std::to_string(k));
      if (lone.running()) {
        expectSame(batch[k + 1][i], lone.step(a[k][i]));
      } else {
        // Autoreset: the first observation, reward 0, neither terminated nor truncated.
        const TaskStep& reset = lone.reset();
        expectSame(batch[k + 1][i], reset);
        EXPECT_EQ(batch[k + 1][i].reward, 0.0);
        EXPECT_FALSE(batch[k + 1][i].terminated || batch[k + 1][i].truncated);
      }
    }
  }
}

TEST(TaskBatch, SameStepAutoresetResetsWithinTheStepThatEndedTheEpisode) {
  ParkingTaskDef def;
  def.fidelity = TaskFidelity::kKinematic;
  def.max_episode_steps = 5;
  const auto a = actions(3, 20);
  TaskBatch batch(testing::studyLot(), def, 3,
                  {.threads = 2, .autoreset = TaskAutoreset::kSameStep});
  batch.reset({std::uint64_t{100}, std::uint64_t{101}, std::uint64_t{102}});
  std::vector<ParkingTask> lone;
  for (std::size_t i = 0; i < 3; ++i) {
    lone.emplace_back(testing::studyLot(), def);
    lone[i].seed(100 + i);
    expectSame(batch.started()[i], lone[i].reset());
  }
  int ends = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    batch.step(a[k]);
    for (std::size_t i = 0; i < 3; ++i) {
      SCOPED_TRACE("task " + std::to_string(i) + " step " + std::to_string(k));
      // Every step is a real one (no step spent on a reset): the lone task's.
      expectSame(batch.last()[i], lone[i].step(a[k][i]));
      if (lone[i].running()) {
        expectSame(batch.started()[i], batch.last()[i]);
      } else {
        ++ends;
        expectSame(batch.started()[i], lone[i].reset());
      }
    }
  }
  EXPECT_EQ(ends, 12);  // 5-step episodes: 4 ends in 20 steps, each task
}

TEST(TaskBatch, RefusesBadActionsBeforeAnyTaskMoves) {
  ParkingTaskDef def;
  def.fidelity = TaskFidelity::kKinematic;
  TaskBatch batch(testing::studyLot(), def, 2, {});
  batch.reset({std::uint64_t{1}, std::uint64_t{2}});
  const Pose2 before = batch.task(0).last().info.pose;
  std::vector<TaskAction> bad = {{0.5, 0.5}, {std::numeric_limits<double>::quiet_NaN(), 0.0}};
  try {
    batch.step(bad);
    FAIL() << "accepted a NaN";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("action 1"), std::string::npos) << e.what();
  }
  EXPECT_EQ(batch.task(0).last().info.pose, before);
  EXPECT_EQ(batch.task(0).steps(), 0);
  EXPECT_THROW(batch.step(std::vector<TaskAction>(3)), Error);
  EXPECT_THROW(batch.reset({std::uint64_t{1}}), Error);
  EXPECT_THROW(TaskBatch(testing::studyLot(), def, 0, {}), Error);
  // Bounded before anything is built: a count or thread number from a typo must not allocate
  // without limit.
  EXPECT_THROW(TaskBatch(testing::studyLot(), def, kMaxBatchTasks + 1, {}), Error);
  EXPECT_THROW(TaskBatch(testing::studyLot(), def, 1000000000, {}), Error);
  EXPECT_THROW(TaskBatch(testing::studyLot(), def, 2, {.threads = kMaxBatchThreads + 1}), Error);
  EXPECT_THROW(TaskBatch(testing::studyLot(), def, 2, {.threads = -1}), Error);
}

}  // namespace
}  // namespace parksim
