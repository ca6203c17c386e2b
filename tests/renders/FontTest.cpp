#include "parksim/renders/text/Font.h"

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/renders/text/FontLookup.h"

namespace parksim {
namespace {

TEST(FontTest, PacksDejaVuAndLaysOutMonospacedText) {
  const std::vector<unsigned char> ttf = readFontFile(findFontFile());
  const FontAtlas atlas(ttf, 18.0f);
  EXPECT_GT(atlas.ascent(), 10.0f);
  EXPECT_GT(atlas.descent(), 2.0f);
  EXPECT_GE(atlas.atlasWidth(), 128);
  EXPECT_EQ(static_cast<std::size_t>(atlas.atlasWidth()) * atlas.atlasHeight(),
            atlas.bitmap().size());
  // Monospaced: every glyph, including the degree sign and theta, advances the same.
  const float one = atlas.advance("a");
  EXPECT_GT(one, 5.0f);
  EXPECT_FLOAT_EQ(atlas.advance("ab\u00b0\u03b8"), 4.0f * one);
  std::vector<GlyphQuad> quads;
  atlas.layout("a b", 10.0f, 30.0f, quads);
  ASSERT_EQ(quads.size(), 2u);  // the space has no pixels
  EXPECT_GE(quads[0].x0, 9.0f);
  EXPECT_LE(quads[0].y1, 30.0f + atlas.descent() + 1.0f);
  EXPECT_GT(quads[1].x0, quads[0].x0 + one);
}

TEST(FontTest, DecodesUtf8AndReplacesBrokenBytes) {
  EXPECT_EQ(decodeUtf8("a\u00b0\u03b8"), (std::vector<char32_t>{U'a', 0xB0, 0x3B8}));
  EXPECT_EQ(decodeUtf8("\xff"), (std::vector<char32_t>{0xFFFD}));
  EXPECT_EQ(decodeUtf8("\xce"), (std::vector<char32_t>{0xFFFD}));  // truncated
}

TEST(FontTest, MissingFontNamesThePackage) {
  try {
    readFontFile("/nonexistent/font.ttf");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("fonts-dejavu-core"), std::string::npos);
  }
  const std::vector<unsigned char> junk(100, 7);
  EXPECT_THROW(FontAtlas(junk, 12.0f), Error);
}

}  // namespace
}  // namespace parksim
