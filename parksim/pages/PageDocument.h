#pragma once
// One page as a single HTML file: the libraries it draws with, parksim's scripts for its kind
// and its data, all inline, so that it opens from file:// inside a CI artifact with no server,
// no network and nothing beside it. A Content-Security-Policy allows no fetch of any kind (no
// script, style, image, font or connection from anywhere, the page's own folder included):
// what is not inline is not loaded. Nor does anything inline run but the page's own files:
// each library, each of parksim's scripts and each style sheet is one element holding the
// file's bytes, allowed by the SHA-256 the build computed (PageAssets.h); an inline script,
// event handler attribute, javascript: link or style attribute from anywhere else (a name
// written into the page as markup by mistake) is refused by the browser. Links to other pages
// are plain navigation.
//
// The data goes into <script type="application/json" id="parksim-data">, except the base64 text
// of its packed columns (ColumnCodec.h), which goes into <script type="text/plain"
// id="parksim-blob-N"> elements (the column keeps "blob": N): no JSON to parse or escape for
// the bulk of the bytes. The page's script reads them (web/common.js), draws, and then sets
// document.body.dataset.ready = "true" (and, with a table, document.body.dataset.rows), which
// tests and benchmarks wait for.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/pages/PageAssets.h"

namespace parksim {

struct PageDocument {
  std::string title;  ///< <title> and the heading's text
  std::vector<PageLibraryId> libraries;
  /// parksim's page scripts after web/common.js, in order ("replay.js", "episode.js").
  std::vector<std::string> scripts;
  /// What the scripts draw; written as JSON (strings that are not UTF-8 with U+FFFD).
  nlohmann::json data;
};

/// The HTML document (taken by value: its packed columns are moved out of the data).
std::string pageHtml(PageDocument page);

/// Writes pageHtml(page) to `path` atomically. Throws Error when it cannot be written.
void writePage(const std::string& path, PageDocument page);

}  // namespace parksim
