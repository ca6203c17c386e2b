// One page, one file: the libraries and parksim's scripts inline, nothing to fetch (its
// Content-Security-Policy allows no request), every library's licence carried with its code.

#include "parksim/pages/PageDocument.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/Verdict.h"
#include "tests/pages/PageTestSupport.h"

namespace parksim {
namespace {

// Whether `html` holds `text` (a failure names the text, not the megabyte of page).
::testing::AssertionResult holds(const std::string& html, std::string_view text) {
  if (html.find(text) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "the page lacks: " << text.substr(0, 120);
}

PageDocument sample() {
  PageDocument doc;
  doc.title = "a & b";
  doc.libraries = {PageLibraryId::kUPlot, PageLibraryId::kTabulator};
  doc.scripts = {"summaries.js"};
  doc.data = {{"page", "test"}, {"text", "x</script>y"}};
  return doc;
}

TEST(PageDocumentTest, EverythingIsInline) {
  const std::string html = pageHtml(sample());
  EXPECT_TRUE(holds(html, "<title>a &amp; b</title>"));
  EXPECT_TRUE(holds(html, "Content-Security-Policy\" content=\"default-src 'none'"));
  // No element loads anything: no src or href attribute, no @import, no url() but data:.
  EXPECT_FALSE(holds(html, " src="));
  EXPECT_FALSE(holds(html, "<link"));
  EXPECT_FALSE(holds(html, "@import"));
  for (const PageLibraryId id : {PageLibraryId::kUPlot, PageLibraryId::kTabulator}) {
    const PageLibrary& lib = pageLibrary(id);
    EXPECT_TRUE(holds(html, std::string(lib.script.substr(0, 200))));
    EXPECT_TRUE(holds(html, std::string(lib.style.substr(0, 200))));
  }
  EXPECT_TRUE(holds(html, pageSource("common.js").substr(0, 200)));
  EXPECT_TRUE(holds(html, std::string(pageSource("summaries.js").substr(0, 200))));
  EXPECT_TRUE(holds(html, std::string(pageSource("page.css").substr(0, 200))));
  EXPECT_EQ(testing::pageData(html), sample().data);
}

TEST(PageDocumentTest, EveryLibraryCarriesItsLicence) {
  const std::string html = pageHtml(sample());
  for (const PageLibraryId id : {PageLibraryId::kUPlot, PageLibraryId::kTabulator}) {
    const PageLibrary& lib = pageLibrary(id);
    EXPECT_EQ(lib.license, "MIT") << lib.package;
    EXPECT_FALSE(lib.version.empty());
    EXPECT_TRUE(holds(std::string(lib.license_text), "Permission is hereby granted"));
    EXPECT_TRUE(holds(html, lib.title + " " + lib.version + " (MIT)"));
  }
  // The licence text itself, escaped for HTML.
  EXPECT_TRUE(holds(html, "THE SOFTWARE IS PROVIDED \"AS IS\""));
}

TEST(PageDocumentTest, OnlyTheLibrariesAPageUsesAreInIt) {
  PageDocument doc = sample();
  doc.libraries = {PageLibraryId::kUPlot};
  const std::string html = pageHtml(doc);
  EXPECT_FALSE(holds(html, pageLibrary(PageLibraryId::kTabulator).script.substr(0, 200)));
}

TEST(PageDocumentTest, EveryStatusHasItsColour) {
  // A status added to the verdict without a colour would show in the failure colour only.
  const std::string_view common = pageSource("common.js");
  for (const EpisodeStatus status : allEpisodeStatuses()) {
    EXPECT_TRUE(holds(std::string(common), std::string("    ") + toString(status) + ": '#"))
        << toString(status);
  }
}

TEST(PageDocumentTest, PageFilesAreNamed) {
  EXPECT_THROW(pageSource("missing.js"), Error);
  const std::vector<std::string> names = embeddedFileNames();
  for (const char* own : {"web/common.js", "web/replay.js", "web/episode.js", "web/summaries.js",
                          "web/sweep.js", "web/comparison.js", "web/page.css"}) {
    EXPECT_THAT(names, ::testing::Contains(own));
  }
}

}  // namespace
}  // namespace parksim
