#include "parksim/sweep/run/SweepJob.h"

#include <algorithm>
#include <set>

#include "parksim/core/io/Error.h"
#include "parksim/results/tables/RowSeal.h"
#include "parksim/sweep/shards/SweepManifest.h"
#include "parksim/sweep/spec/SweepSpecReader.h"

namespace parksim {

SweepPlan prepareSweep(const std::string& spec_path, const Components* extra,
                       const ComponentCheckDef& check) {
  SweepPlan plan;
  plan.spec = loadSweepSpec(spec_path);
  plan.worlds = loadSweepWorlds(plan.spec);
  plan.components = loadSweepComponents(plan.spec, extra);
  plan.episodes = expandEpisodes(plan.spec, plan.worlds, plan.components, check);
  return plan;
}

TableExpectations sweepExpectations(const SweepPlan& plan,
                                    const nlohmann::ordered_json& provenance) {
  TableExpectations expect;
  for (const SweepWorld& w : plan.worlds) {
    expect.world_hashes[w->world.scenario.name] = w->world.content_hash;
  }
  expect.writer = rowWriter(provenance);
  // Each set: path is a column, named by the path.
  for (const SetAxis& axis : plan.spec.set) expect.set_columns.push_back(axis.path);
  // So is each fixed parameter of a planners: or controllers: entry (a command's among them).
  std::set<std::string> fixed;
  for (const ComponentChoice& c : plan.spec.planners) {
    for (const auto& [name, value] : c.params) fixed.insert("planner." + name);
  }
  for (const ComponentChoice& c : plan.spec.controllers) {
    for (const auto& [name, value] : c.params) fixed.insert("controller." + name);
  }
  for (const std::string& column : fixed) {
    if (std::find(expect.set_columns.begin(), expect.set_columns.end(), column) ==
        expect.set_columns.end()) {
      expect.set_columns.push_back(column);
    }
  }
  return expect;
}

SweepJobResult runSweepJob(const SweepPlan& plan, const Shard& shard, const std::string& out,
                           SweepRunnerDef def, const std::function<void(const SweepStart&)>& start,
                           const SweepProgressFn& progress) {
  checkSweepRunnerDef(def);  // before anything is written
  SweepJobResult result;
  result.episodes = selectShard(plan.episodes, shard);
  def.provenance["plugins"] = pluginsProvenance(*plan.components);

  // A table of another id format (an older parksim's) is refused before anything is written.
  SweepManifest existing;
  (void)readSweepManifest(out, existing);
  // Refuses a table with other columns, a changed row, or rows of another world content,
  // build or plugin, before anything is written.
  ResultsTable table(out, sweepExpectations(plan, def.provenance));
  SweepManifest manifest{plan.spec.source_path, plan.spec.name, shard, {}};
  for (const SweepEpisode& e : plan.episodes) manifest.episode_ids.push_back(e.id);
  writeSweepManifest(out, manifest);

  def.episode.record = plan.spec.record;
  def.episode.episodes_dir = out + "/episodes";
  if (start) {
    SweepStart s;
    s.repairs = table.repairs();
    s.episodes = result.episodes.size();
    for (const SweepEpisode& e : result.episodes) s.already += table.done().count(e.id);
    start(s);
  }
  result.progress = runSweep(result.episodes, def, table, progress);
  for (const SweepEpisode& e : result.episodes) result.failed += table.done().at(e.id) ? 0 : 1;
  return result;
}

}  // namespace parksim
