#include "parksim/renders/FontLookup.h"

#include <fontconfig/fontconfig.h>

#include <memory>

#include "parksim/core/Error.h"

namespace parksim {

namespace {

struct ConfigDeleter {
  void operator()(FcConfig* c) const { FcConfigDestroy(c); }
};
struct PatternDeleter {
  void operator()(FcPattern* p) const { FcPatternDestroy(p); }
};
using PatternPtr = std::unique_ptr<FcPattern, PatternDeleter>;

const FcChar8* fc(const char* s) { return reinterpret_cast<const FcChar8*>(s); }
const char* str(const FcChar8* s) { return reinterpret_cast<const char*>(s); }

}  // namespace

std::string findFontFile(const std::string& family) {
  const std::string where = "font '" + family + "'";
  // A configuration of our own rather than fontconfig's process-wide one: nothing global is
  // initialized, and all of it is released here.
  const std::unique_ptr<FcConfig, ConfigDeleter> config(FcInitLoadConfigAndFonts());
  if (!config) throw EnvironmentError(where + ": fontconfig cannot load its configuration");
  const PatternPtr pattern(FcNameParse(fc(family.c_str())));
  FcChar8* wanted = nullptr;
  if (!pattern || FcPatternGetString(pattern.get(), FC_FAMILY, 0, &wanted) != FcResultMatch) {
    throw Error(where + ": not a fontconfig pattern with a family name");
  }
  // stb_truetype draws outline fonts only.
  FcPatternAddBool(pattern.get(), FC_OUTLINE, FcTrue);
  FcConfigSubstitute(config.get(), pattern.get(), FcMatchPattern);
  FcDefaultSubstitute(pattern.get());
  FcResult result = FcResultNoMatch;
  const PatternPtr match(FcFontMatch(config.get(), pattern.get(), &result));
  if (!match) throw EnvironmentError(where + ": fontconfig finds no fonts at all");
  FcChar8* file = nullptr;
  if (FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch) {
    throw Error(where + ": fontconfig's match has no file");
  }
  // fontconfig always answers with something; only the family asked for is taken.
  FcChar8* got = nullptr;
  for (int i = 0; FcPatternGetString(match.get(), FC_FAMILY, i, &got) == FcResultMatch; ++i) {
    if (FcStrCmpIgnoreCase(got, wanted) == 0) return str(file);
  }
  const std::string nearest =
      FcPatternGetString(match.get(), FC_FAMILY, 0, &got) == FcResultMatch ? str(got) : "?";
  throw EnvironmentError(where + ": not installed (fontconfig's nearest is '" + nearest + "', " +
                         str(file) +
                         "); the default font comes with the Debian package fonts-dejavu-core");
}

}  // namespace parksim
