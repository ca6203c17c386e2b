#include "parksim/pipeline/OutcomeFacts.h"

namespace parksim {

namespace {

EpisodeFacts facts(const EpisodeOutcome& out, const EpisodeMetrics* metrics,
                   const Verdict& verdict) {
  EpisodeFacts f;
  f.plan_summary = &out.plan_summary;
  f.plan = out.plan ? &*out.plan : nullptr;
  f.metrics = metrics;
  f.judged = true;
  f.status = toString(verdict.status);
  f.met = verdict.met();
  f.failure = verdict.reason;
  if (out.world) f.world_hash = out.world->content_hash;
  return f;
}

}  // namespace

EpisodeFacts outcomeFacts(const EpisodeOutcome& out) {
  return facts(out, out.driven() ? &out.episode.metrics : nullptr, out.verdict);
}

EpisodeFacts realisationFacts(const EpisodeOutcome& out, std::size_t index) {
  const RealisationOutcome& r = out.realisations.at(index);
  return facts(out, &r.metrics, r.verdict);
}

}  // namespace parksim
