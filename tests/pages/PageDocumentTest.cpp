// One page, one file: the libraries and parksim's scripts inline, nothing to fetch (its
// Content-Security-Policy allows no request), every library's licence carried with its code.

#include "parksim/pages/PageDocument.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/Error.h"
#include "tests/pages/PageTestSupport.h"

namespace parksim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

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
  EXPECT_THAT(html, HasSubstr("<title>a &amp; b</title>"));
  EXPECT_THAT(html, HasSubstr("Content-Security-Policy\" content=\"default-src 'none'"));
  // No element loads anything: no src or href attribute, no @import, no url() but data:.
  EXPECT_THAT(html, Not(HasSubstr(" src=")));
  EXPECT_THAT(html, Not(HasSubstr("<link")));
  EXPECT_THAT(html, Not(HasSubstr("@import")));
  for (const PageLibraryId id : {PageLibraryId::kUPlot, PageLibraryId::kTabulator}) {
    const PageLibrary& lib = pageLibrary(id);
    EXPECT_THAT(html, HasSubstr(std::string(lib.script.substr(0, 200))));
    EXPECT_THAT(html, HasSubstr(std::string(lib.style.substr(0, 200))));
  }
  EXPECT_THAT(html, HasSubstr(std::string(pageSource("common.js").substr(0, 200))));
  EXPECT_THAT(html, HasSubstr(std::string(pageSource("summaries.js").substr(0, 200))));
  EXPECT_THAT(html, HasSubstr(std::string(pageSource("page.css").substr(0, 200))));
  EXPECT_EQ(testing::pageData(html), sample().data);
}

TEST(PageDocumentTest, EveryLibraryCarriesItsLicence) {
  const std::string html = pageHtml(sample());
  for (const PageLibraryId id : {PageLibraryId::kUPlot, PageLibraryId::kTabulator}) {
    const PageLibrary& lib = pageLibrary(id);
    EXPECT_EQ(lib.license, "MIT") << lib.package;
    EXPECT_FALSE(lib.version.empty());
    EXPECT_THAT(std::string(lib.license_text), HasSubstr("Permission is hereby granted"));
    EXPECT_THAT(html, HasSubstr(lib.title + " " + lib.version + " (MIT)"));
  }
  // The licence text itself, escaped for HTML.
  EXPECT_THAT(html, HasSubstr("THE SOFTWARE IS PROVIDED &quot;AS IS&quot;"));
}

TEST(PageDocumentTest, OnlyTheLibrariesAPageUsesAreInIt) {
  PageDocument doc = sample();
  doc.libraries = {PageLibraryId::kUPlot};
  const std::string html = pageHtml(doc);
  EXPECT_THAT(
      html,
      Not(HasSubstr(std::string(pageLibrary(PageLibraryId::kTabulator).script.substr(0, 200)))));
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
