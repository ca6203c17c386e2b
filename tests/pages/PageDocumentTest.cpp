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
    EXPECT_TRUE(holds(html, std::string(lib.script.text.substr(0, 200))));
    EXPECT_TRUE(holds(html, std::string(lib.style.text.substr(0, 200))));
  }
  EXPECT_TRUE(holds(html, pageSource("common.js").text.substr(0, 200)));
  EXPECT_TRUE(holds(html, std::string(pageSource("summaries.js").text.substr(0, 200))));
  EXPECT_TRUE(holds(html, std::string(pageSource("page.css").text.substr(0, 200))));
  EXPECT_EQ(testing::pageData(html), sample().data);
}

// The texts of the page's elements <tag ...>text</tag> whose opening tag is exactly `open`.
std::vector<std::string> elementTexts(const std::string& html, const std::string& open,
                                      const std::string& close) {
  std::vector<std::string> texts;
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at)) {
    at += open.size();
    const std::size_t end = html.find(close, at);
    if (end == std::string::npos) break;
    texts.push_back(html.substr(at, end - at));
    at = end;
  }
  return texts;
}

std::string policyOf(const std::string& html) {
  const std::string key = "Content-Security-Policy\" content=\"";
  const std::size_t at = html.find(key);
  if (at == std::string::npos) return {};
  return html.substr(at + key.size(), html.find('"', at + key.size()) - at - key.size());
}

TEST(PageDocumentTest, OnlyThePagesOwnFilesRunAndStyleItEachByItsHash) {
  const PageDocument doc = sample();
  const std::string html = pageHtml(doc);
  const std::string policy = policyOf(html);
  // No inline script, event handler or javascript: link but those hashed; no eval; no style
  // attribute or element but the page's own sheets.
  EXPECT_THAT(policy, ::testing::Not(::testing::HasSubstr("unsafe")));
  EXPECT_THAT(policy, ::testing::StartsWith("default-src 'none'; script-src 'sha256-"));
  // Each script that runs is one file whole, and the policy names it by its hash: the
  // libraries, then common.js, then the page's own scripts, in order.
  std::vector<PageFile> scripts;
  for (const PageLibraryId id : doc.libraries) scripts.push_back(pageLibrary(id).script);
  for (const char* name : {"common.js", "summaries.js"}) scripts.push_back(pageSource(name));
  const std::vector<std::string> run = elementTexts(html, "<script>", "</script>");
  ASSERT_EQ(run.size(), scripts.size());
  std::string script_src = "script-src";
  for (std::size_t i = 0; i < run.size(); ++i) {
    EXPECT_TRUE(run[i] == scripts[i].text) << "script " << i;
    EXPECT_EQ(scripts[i].sha256_base64.size(), 44u);
    script_src += " 'sha256-" + scripts[i].sha256_base64 + "'";
  }
  EXPECT_THAT(policy, ::testing::HasSubstr(script_src + ";"));
  std::vector<PageFile> styles;
  for (const PageLibraryId id : doc.libraries) styles.push_back(pageLibrary(id).style);
  styles.push_back(pageSource("page.css"));
  const std::vector<std::string> sheets = elementTexts(html, "<style>", "</style>");
  ASSERT_EQ(sheets.size(), styles.size());
  std::string style_src = "style-src";
  for (std::size_t i = 0; i < sheets.size(); ++i) {
    EXPECT_TRUE(sheets[i] == styles[i].text) << "style sheet " << i;
    style_src += " 'sha256-" + styles[i].sha256_base64 + "'";
  }
  EXPECT_THAT(policy, ::testing::HasSubstr(style_src + ";"));
  // Distinct files, distinct hashes.
  EXPECT_NE(pageSource("common.js").sha256_base64, pageSource("summaries.js").sha256_base64);
}

TEST(PageDocumentTest, InlinedFilesHoldNothingTheBrowserWouldReadDifferently) {
  // A browser reads CR LF as LF and NUL as U+FFFD: an element's text would then not have the
  // file's hash, and the policy would refuse it.
  std::vector<std::pair<std::string, std::string_view>> files;
  for (const char* name : {"common.js", "replay.js", "episode.js", "summaries.js", "sweep.js",
                           "comparison.js", "page.css"}) {
    files.emplace_back(name, pageSource(name).text);
  }
  for (const PageLibraryId id : {PageLibraryId::kUPlot, PageLibraryId::kTabulator}) {
    files.emplace_back(pageLibrary(id).title, pageLibrary(id).script.text);
    files.emplace_back(pageLibrary(id).title, pageLibrary(id).style.text);
  }
  for (const auto& [name, text] : files) {
    EXPECT_FALSE(text.empty()) << name;
    EXPECT_EQ(text.find('\r'), std::string_view::npos) << name;
    EXPECT_EQ(text.find('\0'), std::string_view::npos) << name;
  }
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
  EXPECT_FALSE(holds(html, pageLibrary(PageLibraryId::kTabulator).script.text.substr(0, 200)));
}

TEST(PageDocumentTest, EveryStatusHasItsColour) {
  // A status added to the verdict without a colour would show in the failure colour only.
  const std::string_view common = pageSource("common.js").text;
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
