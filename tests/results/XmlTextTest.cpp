// Text from user files escaped for XML: markup, forbidden control characters, bytes that are
// not UTF-8.

#include "parksim/results/reports/XmlText.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(XmlText, MarkupCharactersBecomeEntities) {
  EXPECT_EQ(xmlEscaped("a<b & \"c\" > d", XmlContext::kAttribute),
            "a&lt;b &amp; &quot;c&quot; &gt; d");
  EXPECT_EQ(xmlEscaped("a<b & \"c\"", XmlContext::kContent), "a&lt;b &amp; \"c\"");
  EXPECT_EQ(xmlEscaped("]]>", XmlContext::kContent), "]]&gt;");
}

TEST(XmlText, LineBreaksSurviveInAttributesAsReferences) {
  EXPECT_EQ(xmlEscaped("a\tb\nc\rd", XmlContext::kAttribute), "a&#9;b&#10;c&#13;d");
  EXPECT_EQ(xmlEscaped("a\tb\nc\rd", XmlContext::kContent), "a\tb\nc&#13;d");
}

TEST(XmlText, ControlCharactersXmlForbidsAreShownNotWritten) {
  EXPECT_EQ(
      xmlEscaped(std::string("a\x1b[31mb\x01", 8) + std::string(1, '\0'), XmlContext::kContent),
      "a\\x1b[31mb\\x01\\x00");
  EXPECT_EQ(xmlEscaped("\x7f", XmlContext::kContent), "\\x7f");
  EXPECT_EQ(xmlEscaped("\xc2\x85", XmlContext::kContent), "\\u0085");  // NEL, a C1 control
  EXPECT_EQ(xmlEscaped("\xef\xbf\xbe", XmlContext::kContent), "\\ufffe");
}

TEST(XmlText, BytesThatAreNotUtf8AreNamed) {
  EXPECT_EQ(xmlEscaped("a\xff"
                       "b",
                       XmlContext::kAttribute),
            "a\\xffb");
  EXPECT_EQ(xmlEscaped("\xc3", XmlContext::kAttribute), "\\xc3");                    // truncated
  EXPECT_EQ(xmlEscaped("\xc0\xaf", XmlContext::kAttribute), "\\xc0\\xaf");           // overlong '/'
  EXPECT_EQ(xmlEscaped("\xed\xa0\x80", XmlContext::kAttribute), "\\xed\\xa0\\x80");  // surrogate
}

TEST(XmlText, PrintableUtf8PassesUnchanged) {
  const std::string text = "Parkplatz \xc3\xa4\xc3\xb6 \xe2\x86\x92 \xf0\x9f\x9a\x97 1.5\xc2\xb0";
  EXPECT_EQ(xmlEscaped(text, XmlContext::kAttribute), text);
}

}  // namespace
}  // namespace parksim
