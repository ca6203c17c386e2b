#include "parksim/renders/text/FontCache.h"

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/renders/text/FontLookup.h"

namespace parksim {
namespace {

TEST(FontCacheTest, SizesRoundToWholePixelsOfAtLeastFour) {
  EXPECT_EQ(FontCache::key(15.4f), 15);
  EXPECT_EQ(FontCache::key(15.5f), 16);
  EXPECT_EQ(FontCache::key(1.0f), 4);
  EXPECT_EQ(FontCache::key(-3.0f), 4);
}

TEST(FontCacheTest, PacksEachSizeOnce) {
  FontCache fonts(readFontFile(findFontFile()));
  ASSERT_TRUE(fonts.hasFont());
  const FontAtlas& a = fonts.atlas(15);
  EXPECT_FLOAT_EQ(a.pixelHeight(), 15.0f);
  EXPECT_EQ(&fonts.atlas(15), &a);
  EXPECT_NE(&fonts.atlas(16), &a);
}

TEST(FontCacheTest, WithoutAFontThereIsNoAtlas) {
  FontCache none;
  EXPECT_FALSE(none.hasFont());
  EXPECT_THROW(none.atlas(12), Error);
}

}  // namespace
}  // namespace parksim
