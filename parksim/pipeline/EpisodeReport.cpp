#include "parksim/pipeline/EpisodeReport.h"

#include "parksim/pages/EpisodePage.h"

namespace parksim {

void writeEpisodeReport(const std::string& dir, EpisodeOutcome& out) {
  EpisodePage page;
  page.status = toString(out.verdict.status);
  page.reason = out.verdict.reason;
  page.plan = &out.trajectory;
  page.plan_summary = &out.plan_summary;
  if (out.driven()) {
    page.rows = out.episode.rows;
    page.realism_columns = out.execution.realism.active();
    page.metrics = &out.episode.metrics;
    page.tolerance = &out.tolerance;
    page.realisations = static_cast<int>(out.realisations.size());
    page.realisations_met = out.realisationsMet();
  }
  writeEpisodePage(dir + "/report.html", out.world->scenario, page);
  out.files.push_back("report.html");
}

}  // namespace parksim
