#include "parksim/renders/text/FontLookup.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "parksim/core/io/Error.h"
#include "parksim/renders/text/Font.h"

namespace parksim {
namespace {

std::string fileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

// fonts-dejavu-core is installed by scripts/install-deps.sh.
TEST(FontLookupTest, FindsDejaVuSansMonoThroughFontconfig) {
  const std::string path = findFontFile();
  EXPECT_EQ(fileName(path), "DejaVuSansMono.ttf") << path;
  EXPECT_TRUE(std::filesystem::is_regular_file(path)) << path;
  const FontAtlas atlas(readFontFile(path), 16.0f);  // a font stb_truetype reads
  EXPECT_GT(atlas.advance("a"), 4.0f);
  // A fontconfig pattern, not only a family name.
  EXPECT_EQ(fileName(findFontFile("DejaVu Sans Mono:bold")), "DejaVuSansMono-Bold.ttf");
  EXPECT_EQ(fileName(findFontFile("dejavu sans mono")), "DejaVuSansMono.ttf");
}

TEST(FontLookupTest, MissingFamilyIsAnErrorNotASubstitute) {
  try {
    findFontFile("No Such Family Parksim");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("font 'No Such Family Parksim': not installed"), std::string::npos) << what;
    EXPECT_NE(what.find("fonts-dejavu-core"), std::string::npos) << what;
  }
  EXPECT_THROW(findFontFile(""), Error);
}

}  // namespace
}  // namespace parksim
