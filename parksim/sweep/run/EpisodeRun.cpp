#include "parksim/sweep/run/EpisodeRun.h"

#include <chrono>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/OutcomeFacts.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/sweep/spec/EpisodeSetup.h"

namespace parksim {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The sweep's recording choices as the pipeline's: which episodes keep files, at which row
// rate, and the film of a failure.
void applyRecord(const EpisodeRunDef& def, const std::string& dir, EpisodeRequest& r) {
  r.out_dir = dir;
  r.record.files = def.record.executed_csv;
  r.record.executed_rate_hz = def.record.executed_rate_hz;
  r.record.format = def.record.format;
  if (!def.record.film_failures) return;
  if (def.film_mutex == nullptr) throw Error("runSweepEpisode: filming needs a film_mutex");
  r.film.when = FilmWhen::kOnFailure;
  r.film.lock = def.film_mutex;
  r.film.frames.fps = def.record.film_fps;
  r.film.frames.width_px = def.record.film_width_px;
  r.film.frames.height_px = def.record.film_height_px;
  r.film.frames.view = frameViewFromString(def.record.film_view);
  r.film.frames.video = def.record.film_video;
}

}  // namespace

EpisodeRequest sweepEpisodeRequest(const SweepEpisode& episode) {
  static const ToleranceOverrides kNoOverrides;
  return episodeRequest(episode.params, episodeWorld(episode.params, episode.world),
                        episode.tolerance ? *episode.tolerance : kNoOverrides, episode.components);
}

nlohmann::ordered_json runSweepEpisode(const SweepEpisode& episode, const EpisodeRunDef& def,
                                       UserCodeWatch* watch) {
  const Clock::time_point t0 = Clock::now();
  EpisodeRequest request = sweepEpisodeRequest(episode);
  request.watch = watch;
  request.limits = def.limits;
  applyRecord(def, def.episodes_dir + "/" + episode.id, request);
  const EpisodeOutcome out = runEpisodePipeline(request);

  EpisodeFacts facts = outcomeFacts(out);
  // Which content of the world file the episode ran on: its name alone (in the id) cannot tell
  // an edited file from the one an earlier run used. The file's, without the spec's set:
  // values (those are columns and part of the id).
  facts.world_hash = episode.world->world.content_hash;
  facts.episode_wall_s = secondsSince(t0);
  nlohmann::ordered_json row = episodeRow(episode.id, episode.params, facts);
  return row;
}

nlohmann::ordered_json failedEpisodeRow(const SweepEpisode& episode, const Verdict& verdict) {
  EpisodeFacts facts;
  facts.judged = true;
  facts.status = toString(verdict.status);
  facts.met = false;
  facts.failure = verdict.reason;
  facts.world_hash = episode.world->world.content_hash;
  return episodeRow(episode.id, episode.params, facts);
}

nlohmann::ordered_json episodeRow(const std::string& id, const EpisodeParams& params,
                                  const EpisodeFacts& facts) {
  nlohmann::ordered_json row;
  if (!id.empty()) row["episode_id"] = id;
  appendParamColumns(params, row);
  appendRecord(facts, row);
  return row;
}

std::vector<nlohmann::ordered_json> realisationRecords(const EpisodeRequest& request,
                                                       const EpisodeOutcome& outcome) {
  EpisodeParams params = episodeParamsOf(request);
  std::vector<nlohmann::ordered_json> records;
  if (!outcome.driven()) {
    records.push_back(episodeRow("", params, outcomeFacts(outcome)));
    return records;
  }
  for (std::size_t i = 0; i < outcome.realisations.size(); ++i) {
    params.noise_seed = outcome.realisations[i].noise_seed;
    records.push_back(episodeRow("", params, realisationFacts(outcome, i)));
  }
  return records;
}

}  // namespace parksim
