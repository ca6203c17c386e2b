#include "parksim/results/tables/TableVerify.h"

#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "parksim/results/tables/ResultsFile.h"

namespace parksim {
namespace fs = std::filesystem;

void verifyTable(const std::string& dir, const std::vector<std::string>* expected_ids,
                 std::size_t max_listed, TableVerification& v) {
  const std::string jsonl = dir + "/results.jsonl";
  const std::string csv_path = dir + "/results.csv";
  v.tables.push_back(jsonl);
  std::size_t listed = 0;
  const auto problem = [&](const std::string& text) {
    if (listed < max_listed) {
      v.problems.push_back(text);
      ++listed;
    } else {
      ++v.unlisted;
    }
  };
  const auto at = [](const std::string& file, std::size_t line) {
    return file + ":" + std::to_string(line) + ": ";
  };

  std::error_code ec;
  const bool csv_exists = fs::exists(csv_path, ec);
  CsvFollower csv(csv_path);
  enum class Csv { kFollowing, kEnded, kIgnored } state = Csv::kFollowing;
  std::size_t csv_behind = 0;
  std::vector<std::string> columns;            // results.csv's, from its header
  std::set<std::string, std::less<>> csv_set;  // its set columns
  std::set<std::string, std::less<>> row_set;  // the set keys of the rows
  if (!csv_exists) {
    problem(csv_path + ": missing (a sweep opening this table rebuilds it from results.jsonl)");
    state = Csv::kIgnored;
  } else {
    std::string header;
    std::optional<std::vector<std::string>> set;
    if (csv.nextLine(header)) set = setColumnsOfHeader(header);
    if (set) {
      columns = resultColumns(*set);
      csv_set.insert(set->begin(), set->end());
    } else {
      problem(at(csv_path, 1) + "header is not this parksim's columns (another version's table?)");
      state = Csv::kIgnored;
    }
  }

  std::map<std::string, std::size_t> first_line;
  TableOrigins origins;
  const TableScan scan = scanResultsJsonl(
      jsonl,
      [&](const TableRow& r) {
        const std::string id = r.row["episode_id"].get<std::string>();
        const auto [it, inserted] = first_line.emplace(id, r.line);
        if (!inserted) {
          problem(at(jsonl, r.line) + "episode " + id + " again (first at line " +
                  std::to_string(it->second) + ")");
        }
        origins.add(r.row, jsonl, r.line);
        addSetKeys(r.row, row_set);
        ++v.rows;
        if (state == Csv::kEnded) ++csv_behind;
        if (state != Csv::kFollowing) return;
        switch (csv.next(csvRow(r.row, columns))) {
          case CsvFollower::Match::kSame: break;
          case CsvFollower::Match::kEnded:
            state = Csv::kEnded;
            csv_behind = 1;
            break;
          case CsvFollower::Match::kDiffers:
            problem(at(csv_path, csv.line()) + "differs from the row of " + jsonl + ":" +
                    std::to_string(r.line) + " (episode " + id +
                    "): results.csv changed after parksim wrote it");
            csv.skipLine();  // rows are one line each: go on with the next
            break;
        }
      },
      [&](std::size_t line, const std::string& what) {
        problem(at(jsonl, line) + what);
        if (state == Csv::kFollowing) csv.skipLine();
      });

  if (scan.torn_tail) {
    v.notes.push_back(jsonl +
                      ": ends in a torn row (a sweep stopped while writing it); the next "
                      "sweep into this directory cuts it off and runs that episode again");
  }
  if (state == Csv::kEnded) {
    if (csv_behind == 1) {
      v.notes.push_back(csv_path +
                        ": lacks the last row of results.jsonl (a sweep stopped "
                        "between the two files); the next sweep rebuilds it");
    } else {
      problem(at(csv_path, csv.line()) + "ends here, " + std::to_string(csv_behind) +
              " rows of results.jsonl short");
    }
  } else if (state == Csv::kFollowing && csv.hasMore()) {
    problem(at(csv_path, csv.line()) + "rows beyond those of results.jsonl");
  }
  if (state != Csv::kIgnored) {
    for (const std::string& key : row_set) {
      if (csv_set.count(key) == 0) {
        problem(at(csv_path, 1) + "has no column " + key + ", which rows of " + jsonl + " have");
      }
    }
  }
  for (const std::string& mix : origins.mixes()) problem(mix);

  if (expected_ids != nullptr) {
    std::size_t missing = 0;
    for (const std::string& id : *expected_ids) missing += first_line.count(id) == 0;
    if (missing > 0) {
      v.notes.push_back(jsonl + ": " + std::to_string(missing) + " of the sweep's " +
                        std::to_string(expected_ids->size()) +
                        " episodes are not in the table (yet)");
    }
  }
}

}  // namespace parksim
