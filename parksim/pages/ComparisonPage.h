#pragma once
// A comparison's page (`parksim compare BASELINE CANDIDATE --html FILE`): every group, the
// baseline against the candidate with their intervals and Holm-adjusted p-values, regressed
// groups first; each group links to its paired episodes where both sweeps kept their pages,
// the worst changes first (web/comparison.js; docs/pages.md).

#include <string>

#include <nlohmann/json.hpp>

namespace parksim {

struct ComparisonPage {
  /// The comparison as data (compare/ComparisonJson.h's comparisonJson), with, when the
  /// caller found them, "differences": what differs between the two configurations
  /// (compare/ConfigurationDiff.h's differencesJson), which the page lists first.
  nlohmann::json comparison;
  /// The sweep directories whose episodes/<id>/report.html the page links to (the candidate's
  /// by an episode's candidate_id where it has one); empty for a table given as a
  /// results.jsonl file outside a sweep directory.
  std::string baseline_dir;
  std::string candidate_dir;
  /// Episodes linked per group at most (the worst changes first).
  int max_links_per_group = 50;
};

/// The page's data: the comparison, with each group's "episodes" cut to those whose pages
/// both sweeps kept (at most max_links_per_group, with "baseline_href" and "candidate_href"
/// relative to `page_dir`, the folder the page is written to, as URL references: hrefOf) and
/// "paired_episodes" / "linked_episodes" counting what was there and what is linked.
nlohmann::json comparisonPageData(const ComparisonPage& page, const std::string& page_dir);

/// Writes the page to `path` atomically. Throws Error.
void writeComparisonPage(const std::string& path, const ComparisonPage& page);

}  // namespace parksim
