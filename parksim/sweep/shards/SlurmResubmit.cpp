#include "parksim/sweep/shards/SlurmResubmit.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "parksim/core/io/Error.h"
#include "parksim/core/system/Process.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/shards/Shard.h"

namespace parksim {

std::vector<ShardState> slurmShardStates(const std::string& dir,
                                         const std::vector<SweepEpisode>& episodes, int shards) {
  std::vector<ShardState> states;
  for (int i = 0; i < shards; ++i) {
    ShardState s;
    s.index = i;
    std::vector<std::string> ids;
    for (const SweepEpisode& e : selectShard(episodes, Shard{i, shards})) ids.push_back(e.id);
    s.episodes = ids.size();  // canonical order is ascending id: ids is sorted
    const std::string shard_dir = dir + "/shards/" + std::to_string(i);
    s.running = resultsTableBusy(shard_dir);
    std::vector<bool> seen(ids.size(), false);
    scanResultsJsonl(shard_dir + "/results.jsonl", [&](const TableRow& r) {
      const std::string& id = r.row["episode_id"].get_ref<const std::string&>();
      const auto it = std::lower_bound(ids.begin(), ids.end(), id);
      if (it != ids.end() && *it == id) seen[static_cast<std::size_t>(it - ids.begin())] = true;
    });
    s.done = static_cast<std::size_t>(std::count(seen.begin(), seen.end(), true));
    states.push_back(s);
  }
  return states;
}

std::string arrayList(const std::vector<ShardState>& states) {
  std::string list;
  for (const ShardState& s : states) {
    if (s.complete() || s.running) continue;
    if (!list.empty()) list += ',';
    list += std::to_string(s.index);
  }
  return list;
}

Submission submitArrayTasks(const std::string& script, const std::string& array_list, bool wait,
                            const std::string& log_path) {
  const std::string sbatch = findExecutable("sbatch");
  if (sbatch.empty()) {
    throw EnvironmentError(
        "sbatch: not found on PATH (is this a Slurm login node?); submit by "
        "hand: sbatch --array=" +
        array_list + " " + script);
  }
  std::vector<std::string> argv = {sbatch, "--parsable", "--array=" + array_list};
  if (wait) argv.push_back("--wait");
  argv.push_back(script);
  const ProcessResult r = runProcess(argv, log_path);
  std::ifstream in(log_path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string output = text.str();
  if (!r.started) throw EnvironmentError("sbatch: " + r.error);
  Submission s;
  s.exit_code = r.exit_code;
  // --parsable: the first line is "jobid" or "jobid;cluster".
  const std::string first = output.substr(0, output.find('\n'));
  const bool numeric = !first.empty() && std::isdigit(static_cast<unsigned char>(first[0]));
  if (!numeric) {
    throw Error("sbatch --array=" + array_list + " " + script + " did not submit (exit status " +
                std::to_string(r.exit_code) + "): " + output.substr(0, 300));
  }
  s.job_id = first.substr(0, first.find(';'));
  return s;
}

}  // namespace parksim
