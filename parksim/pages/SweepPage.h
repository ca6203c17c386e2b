#pragma once
// A sweep's page, DIR/report/index.html (`parksim report DIR`): every episode in a table that
// sorts by any column and filters by status and by any column or axis; per axis that varies,
// each value's met fraction with its 95 % interval and the error quantiles, over the episodes
// the filters leave (so a filter to one world shows that world's study); each kept episode
// linked to its own page (EpisodePage.h). The table is read generically (TableColumns.h):
// columns and axes a later parksim adds show up without a change here (web/sweep.js;
// docs/pages.md).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

struct SweepPage {
  std::string title;   ///< the sweep's name
  std::string source;  ///< the sweep directory, as the user named it
  /// The table's rows (readVerifiedTable), in file order.
  const std::vector<nlohmann::ordered_json>* rows = nullptr;
  /// The columns that are the sweep's parameters (parameterColumns); those that vary get a
  /// summary.
  std::vector<std::string> axes;
  /// Every status an episode can have, in judging order (allEpisodeStatuses), so that the page
  /// offers and counts each, none seen included.
  std::vector<std::string> statuses;
  /// Where the episode folders are, relative to the page, as a URL reference ("../episodes",
  /// hrefOf(relativeHref(...))); and for each row
  /// whether its folder holds a page (keptEpisodePages).
  std::string episodes_href;
  std::vector<bool> kept;
  /// Lines to show above the table (a table mixing builds or world contents).
  std::vector<std::string> warnings;
};

/// The parameters of a results table: the keys a row lists between episode_id and status, in
/// that order (the layout sweep rows are written in: id, parameters, outcome, measurements),
/// but the replicates (isReplicateKey: seed, noise_seed, sample), which are no axis.
std::vector<std::string> parameterColumns(const std::vector<nlohmann::ordered_json>& rows);

/// `episodes_dir`/<id>/report.html when it is a whole page (isWholePage, EpisodeFolderCheck.h),
/// else an empty path (also for an id that is not a folder name: empty, ".", "..", or holding
/// a separator): a page cut short is not linked.
std::filesystem::path keptEpisodePage(const std::string& episodes_dir, const std::string& id);

/// For each row, whether its episode has a page (keptEpisodePage of its episode_id).
std::vector<bool> keptEpisodePages(const std::string& episodes_dir,
                                   const std::vector<nlohmann::ordered_json>& rows);

/// A path from folder `from` to `to` (both as given; relative ones from the working directory),
/// with '/' separators, as it is (JUnit's properties hold it so; a page's link holds hrefOf it).
std::string relativeHref(const std::string& from, const std::string& to);

/// A '/'-separated path as a URL reference a page's link can hold: every byte but the
/// unreserved ones (A-Z a-z 0-9 - . _ ~) and '/' percent-encoded, so that a folder named
/// "javascript:x" is not read as a scheme, nor '?' or '#' as a query or fragment, and '%' and
/// spaces survive.
std::string hrefOf(std::string_view path);

/// The page's data: {"page": "sweep", "title", "source", "table": tableColumns(rows), "axes",
/// "statuses", "episodes": {"href", "kept": codes}, "warnings"}.
nlohmann::json sweepPageData(const SweepPage& page);

/// Writes the page to `path` atomically. Throws Error.
void writeSweepPage(const std::string& path, const SweepPage& page);

}  // namespace parksim
