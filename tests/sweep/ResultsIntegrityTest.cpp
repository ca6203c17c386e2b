// The integrity of results tables (issue 22, item 3): every row sealed, a changed byte found
// with its file and line by every reader, rows of another world content or build refused on
// resume and flagged by merge and verify, a failed write taken back, one writer at a time.
// Rows here are small hand-made ones: no episode runs.

#include <sys/resource.h>

#include <csignal>
#include <filesystem>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/results/tables/RowSeal.h"
#include "parksim/results/tables/TableVerify.h"
#include "parksim/sweep/shards/Merge.h"
#include "tests/support/RunParksim.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace results_integrity_test {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using testing::scratchDir;
using testing::slurp;
using testing::writeText;

Json row(int i, const std::string& world_hash = "00000000000000aa",
         const std::string& version = "0.3.0") {
  Json r;
  r["episode_id"] = "00000000000000" + std::string(i < 10 ? "0" : "") + std::to_string(i);
  r["world"] = "head_in";
  r["planner"] = "rrt";
  r["seed"] = i;
  r["met_tolerance"] = i % 3 != 0;
  r["failure"] = i % 3 != 0 ? "" : "goal missed: 3.2 mm, \"far\"";
  r["max_pos_err_m"] = 0.0001 * i;
  r["contact_bodies"] = Json::array({"wall", "robot_1"});
  r["plan_cost_history"] = Json::array({Json::array({0.01, 5, 1.5})});
  r[std::string(kWorldHashKey)] = world_hash;
  r["parksim_version"] = version;
  r["git_commit"] = "0123456789abcdef";
  r["git_dirty"] = false;
  r["build_type"] = "Release";
  r["compiler"] = "GNU 12.2.0";
  r["bullet_precision"] = "double";
  r["host"] = "h";
  return r;
}

void appendRows(const std::string& dir, int from, int to,
                const std::string& hash = "00000000000000aa",
                const std::string& version = "0.3.0") {
  ResultsTable table(dir);
  for (int i = from; i < to; ++i) table.append(row(i, hash, version));
}

// Flips one bit of the byte at `offset` of `path`.
void flip(const std::string& path, std::size_t offset) {
  std::string text = slurp(path);
  ASSERT_LT(offset, text.size());
  text[offset] = static_cast<char>(text[offset] ^ 0x04);
  writeText(path, text);
}

// Offset of the first byte of 1-based `line` + `column`.
std::size_t offsetOf(const std::string& path, int line, std::size_t column) {
  const std::string text = slurp(path);
  std::size_t at = 0;
  for (int l = 1; l < line; ++l) at = text.find('\n', at) + 1;
  return at + column;
}

template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(RowSeal, EverySingleChangedByteOfARowIsFound) {
  const SealedRow sealed = sealRow(row(7));
  ASSERT_FALSE(sealProblem(sealed.line)) << sealed.line;
  EXPECT_EQ(Json::parse(sealed.line)[std::string(kRowChecksumKey)], sealed.checksum);
  EXPECT_THROW(sealRow(Json::parse(sealed.line)), Error);  // sealed twice
  // Every byte, every bit: FNV-1a's steps are bijections, so no change can keep the checksum.
  for (std::size_t i = 0; i < sealed.line.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      std::string changed = sealed.line;
      changed[i] = static_cast<char>(changed[i] ^ (1 << bit));
      EXPECT_TRUE(sealProblem(changed)) << "byte " << i << " bit " << bit;
    }
  }
  EXPECT_TRUE(sealProblem(row(7).dump()));  // unsealed
}

TEST(ResultsIntegrity, AChangedRowIsFoundWithItsFileAndLineByEveryReader) {
  const std::string dir = scratchDir();
  appendRows(dir, 1, 6);
  const std::string jsonl = dir + "/results.jsonl";
  ASSERT_EQ(readResultsJsonl(jsonl).size(), 5u);
  ASSERT_TRUE(verifyResults(dir).ok());
  // A digit of max_pos_err_m in the third row: still valid JSON, still a number.
  const std::string third = slurp(jsonl).substr(offsetOf(jsonl, 3, 0));
  flip(jsonl, offsetOf(jsonl, 3, third.find("max_pos_err_m") + 18));
  const std::string expected = jsonl + ":3: row_checksum ";
  EXPECT_EQ(errorOf([&] { readResultsJsonl(jsonl); }).rfind(expected, 0), 0u);
  EXPECT_EQ(errorOf([&] { ResultsTable table(dir); }).rfind(expected, 0), 0u);
  EXPECT_EQ(errorOf([&] { mergeResults({dir}); }).rfind(expected, 0), 0u);
  EXPECT_EQ(errorOf([&] { readVerifiedTable(dir); }).rfind(expected, 0), 0u);
  // verify lists every changed row, not just the first; results.csv is judged against the rows
  // it can still trust.
  flip(jsonl, offsetOf(jsonl, 5, 3));  // the fifth row's key name
  const TableVerification v = verifyResults(dir);
  ASSERT_EQ(v.problems.size(), 2u);
  EXPECT_EQ(v.problems[0].rfind(expected, 0), 0u) << v.problems[0];
  EXPECT_EQ(v.problems[1].rfind(jsonl + ":5: row_checksum ", 0), 0u) << v.problems[1];
  EXPECT_EQ(v.rows, 3u);
}

TEST(ResultsIntegrity, AChangedLineOfTheCsvIsFoundAndRefusedOnResume) {
  const std::string dir = scratchDir();
  appendRows(dir, 1, 4);
  const std::string csv = dir + "/results.csv";
  flip(csv, offsetOf(csv, 3, 20));  // the second row (line 3; line 1 is the header)
  EXPECT_EQ(errorOf([&] { ResultsTable table(dir); }),
            csv + ":3: differs from the row of " + dir +
                "/results.jsonl:2 (episode 0000000000000002): results.csv changed after parksim "
                "wrote it; results.jsonl is the reference: remove results.csv and run again to "
                "rebuild it");
  const TableVerification v = verifyResults(dir);
  ASSERT_EQ(v.problems.size(), 1u);
  EXPECT_EQ(v.problems[0].rfind(csv + ":3: differs from the row of ", 0), 0u) << v.problems[0];
  // Removed, it is rebuilt from results.jsonl.
  fs::remove(csv);
  { ResultsTable table(dir); }
  EXPECT_TRUE(verifyResults(dir).ok());
}

TEST(ResultsIntegrity, ResumeRefusesRowsOfAnotherWorldContentOrBuild) {
  const std::string dir = scratchDir();
  appendRows(dir, 1, 3);
  const Json provenance = row(0);
  TableExpectations same{{{"head_in", "00000000000000aa"}}, rowWriter(provenance), {}};
  EXPECT_NO_THROW(ResultsTable table(dir, same));
  TableExpectations edited{{{"head_in", "00000000000000bb"}}, "", {}};
  EXPECT_EQ(errorOf([&] { ResultsTable table(dir, edited); }),
            dir +
                "/results.jsonl:1: episode 0000000000000001 ran on another content of world "
                "'head_in' (world_hash 00000000000000aa; the world file now: "
                "00000000000000bb): the world file changed since; sweep into a new --out (or "
                "restore the file)");
  TableExpectations rebuilt{{}, rowWriter(row(0, "00000000000000aa", "0.3.1")), {}};
  EXPECT_NE(errorOf([&] { ResultsTable table(dir, rebuilt); })
                .find("was written by parksim 0.3.0 (commit 0123456789ab, Release, GNU 12.2.0, "
                      "Bullet double), not by this parksim 0.3.1"),
            std::string::npos);
  // Rows of a world the sweep does not read (an edited spec) are kept as they are.
  TableExpectations other{{{"parallel", "00000000000000cc"}}, "", {}};
  EXPECT_NO_THROW(ResultsTable table(dir, other));
}

TEST(ResultsIntegrity, MergeAndVerifyFlagTablesMixingWorldContentsOrBuilds) {
  const std::string dir = scratchDir();
  appendRows(dir + "/shards/0", 1, 3);
  appendRows(dir + "/shards/1", 3, 5, "00000000000000bb");
  appendRows(dir + "/shards/2", 5, 7, "00000000000000aa", "0.3.1");
  const MergeResult r = mergeResults(mergeSources(dir));
  ASSERT_EQ(r.mixes.size(), 2u);
  EXPECT_EQ(r.mixes[0], dir +
                            "/shards/1/results.jsonl:1: world 'head_in' has another content "
                            "(world_hash 00000000000000bb) than at " +
                            dir +
                            "/shards/0/results.jsonl:1 (00000000000000aa): the world file "
                            "changed between runs");
  EXPECT_NE(r.mixes[1].find("results of two builds"), std::string::npos) << r.mixes[1];
  EXPECT_EQ(r.rows.size(), 6u);
  const TableVerification v = verifyResults(dir);
  EXPECT_TRUE(v.problems.empty());  // each shard on its own is one world content and build
  writeMergedTable(dir, r);
  const TableVerification merged = verifyResults(dir);
  EXPECT_EQ(merged.problems.size(), 2u);
}

TEST(ResultsIntegrity, MergedTableCopiesEachRowAsWrittenAndIsIdempotent) {
  const std::string dir = scratchDir();
  appendRows(dir + "/shards/0", 1, 4);
  appendRows(dir + "/shards/1", 4, 9);
  writeMergedTable(dir, mergeResults(mergeSources(dir)));
  const std::string once = slurp(dir + "/results.jsonl");
  EXPECT_TRUE(verifyResults(dir).ok());
  // Again, with the merged table among the sources: the same bytes, every row duplicated.
  std::vector<std::string> sources = mergeSources(dir);
  sources.push_back(dir);
  const MergeResult twice = mergeResults(sources);
  EXPECT_EQ(twice.duplicated.size(), 8u);
  EXPECT_TRUE(twice.conflicting.empty());
  writeMergedTable(dir, twice);
  EXPECT_EQ(slurp(dir + "/results.jsonl"), once);
  EXPECT_FALSE(fs::exists(dir + "/results.jsonl.tmp"));
}

// A write that fails (here a file-size limit; a full disk the same) takes the row back from
// both files: they keep whole rows and agree, and the next append works once there is room.
TEST(ResultsIntegrity, AFailedAppendLeavesBothFilesWholeAndAgreeing) {
  const std::string dir = scratchDir();
  ResultsTable table(dir);
  table.append(row(1));
  const auto jsonl_size = fs::file_size(dir + "/results.jsonl");
  const auto csv_size = fs::file_size(dir + "/results.csv");
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  // Room for part of a row in results.jsonl, and for a whole one in results.csv only.
  rlimit small = old;
  small.rlim_cur = static_cast<rlim_t>(std::max(jsonl_size, csv_size) + 100);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string why = errorOf([&] { table.append(row(2)); });
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &old), 0);
  EXPECT_NE(why.find("write failed: File too large"), std::string::npos) << why;
  EXPECT_EQ(fs::file_size(dir + "/results.jsonl"), jsonl_size);
  EXPECT_EQ(fs::file_size(dir + "/results.csv"), csv_size);
  EXPECT_EQ(table.done().count(row(2)["episode_id"].get<std::string>()), 0u);
  table.append(row(2));
  table.sync();
  EXPECT_TRUE(verifyResults(dir).ok());
}

TEST(ResultsIntegrity, OneWriterAtATimeAndTornRowsRepairedWithANote) {
  const std::string dir = scratchDir();
  {
    ResultsTable table(dir);
    table.append(row(1));
    table.append(row(2));
    EXPECT_NE(errorOf([&] { ResultsTable second(dir); }).find("another parksim sweep is writing"),
              std::string::npos);
    EXPECT_TRUE(resultsTableBusy(dir));
  }
  EXPECT_FALSE(resultsTableBusy(dir));
  // A kill between the two files: the second row is in results.jsonl, not in results.csv.
  const std::string jsonl = dir + "/results.jsonl";
  const std::string csv = dir + "/results.csv";
  fs::resize_file(csv, offsetOf(csv, 3, 0));
  TableVerification v = verifyResults(dir);
  EXPECT_TRUE(v.problems.empty());
  ASSERT_EQ(v.notes.size(), 1u);
  EXPECT_NE(v.notes[0].find("lacks the last row of results.jsonl"), std::string::npos);
  {
    ResultsTable table(dir);
    ASSERT_EQ(table.repairs().size(), 1u);
    EXPECT_NE(table.repairs()[0].find("results.csv: rebuilt from results.jsonl (2 rows)"),
              std::string::npos)
        << table.repairs()[0];
  }
  EXPECT_TRUE(verifyResults(dir).ok());
  EXPECT_TRUE(verifyResults(dir).notes.empty());
  // A kill in the middle of the second row's write to results.jsonl, before results.csv.
  fs::resize_file(jsonl, offsetOf(jsonl, 2, 30));
  fs::resize_file(csv, offsetOf(csv, 3, 0));
  v = verifyResults(dir);
  EXPECT_TRUE(v.problems.empty());
  ASSERT_EQ(v.notes.size(), 1u);
  EXPECT_NE(v.notes[0].find("ends in a torn row"), std::string::npos);
  ResultsTable table(dir);
  ASSERT_EQ(table.repairs().size(), 1u);
  EXPECT_NE(table.repairs()[0].find("cut off a torn last row"), std::string::npos);
  EXPECT_EQ(table.done().size(), 1u);
  EXPECT_EQ(fs::file_size(jsonl), offsetOf(jsonl, 2, 0));
}

TEST(ResultsIntegrity, UnsealedRowsAreRefusedAsNotParksims) {
  const std::string dir = scratchDir();
  writeText(dir + "/results.jsonl", row(1).dump() + "\n");
  EXPECT_EQ(errorOf([&] { readResultsJsonl(dir + "/results.jsonl"); }),
            dir +
                "/results.jsonl:1: no row_checksum as its last key: not a row this parksim "
                "wrote (a hand-written row, a damaged end of line, or a table of parksim 0.3.0 "
                "or earlier)");
}

}  // namespace results_integrity_test
}  // namespace parksim
