#include "parksim/renders/text/FontLookup.h"

#include <fontconfig/fontconfig.h>

#include <memory>

#include "parksim/core/io/Error.h"
#include "parksim/core/system/SharedLibrary.h"

namespace parksim {

namespace {

// X(Name): FcName, typed by <fontconfig/fontconfig.h>'s declaration. Exactly the functions used
// here.
#define PARKSIM_FC_FUNCTIONS(X) \
  X(ConfigDestroy)              \
  X(ConfigSubstitute)           \
  X(DefaultSubstitute)          \
  X(FontMatch)                  \
  X(InitLoadConfigAndFonts)     \
  X(NameParse)                  \
  X(PatternAddBool)             \
  X(PatternDestroy)             \
  X(PatternGetString)           \
  X(StrCmpIgnoreCase)

// libfontconfig (and FreeType, libpng and Brotli behind it), loaded for the lookup: a process
// that draws no text does not map them. Never called directly (nothing links it).
struct Fontconfig {
  SharedLibrary library{PARKSIM_FONTCONFIG_LIBRARY, "fontconfig",
                        "install the Debian package libfontconfig1"};
#define PARKSIM_FC_MEMBER(name) \
  decltype(&::Fc##name) name = library.function<decltype(&::Fc##name)>("Fc" #name);
  PARKSIM_FC_FUNCTIONS(PARKSIM_FC_MEMBER)
#undef PARKSIM_FC_MEMBER
};

struct ConfigDeleter {
  const Fontconfig* fc;
  void operator()(FcConfig* c) const { fc->ConfigDestroy(c); }
};
struct PatternDeleter {
  const Fontconfig* fc;
  void operator()(FcPattern* p) const { fc->PatternDestroy(p); }
};
using PatternPtr = std::unique_ptr<FcPattern, PatternDeleter>;

const FcChar8* bytes(const char* s) { return reinterpret_cast<const FcChar8*>(s); }
const char* str(const FcChar8* s) { return reinterpret_cast<const char*>(s); }

}  // namespace

std::string findFontFile(const std::string& family) {
  const std::string where = "font '" + family + "'";
  const Fontconfig fc;
  // A configuration of our own rather than fontconfig's process-wide one: nothing global is
  // initialized, and all of it is released here.
  const std::unique_ptr<FcConfig, ConfigDeleter> config(fc.InitLoadConfigAndFonts(), {&fc});
  if (!config) throw EnvironmentError(where + ": fontconfig cannot load its configuration");
  const PatternPtr pattern(fc.NameParse(bytes(family.c_str())), {&fc});
  FcChar8* wanted = nullptr;
  if (!pattern || fc.PatternGetString(pattern.get(), FC_FAMILY, 0, &wanted) != FcResultMatch) {
    throw Error(where + ": not a fontconfig pattern with a family name");
  }
  // stb_truetype draws outline fonts only.
  fc.PatternAddBool(pattern.get(), FC_OUTLINE, FcTrue);
  fc.ConfigSubstitute(config.get(), pattern.get(), FcMatchPattern);
  fc.DefaultSubstitute(pattern.get());
  FcResult result = FcResultNoMatch;
  const PatternPtr match(fc.FontMatch(config.get(), pattern.get(), &result), {&fc});
  if (!match) throw EnvironmentError(where + ": fontconfig finds no fonts at all");
  FcChar8* file = nullptr;
  if (fc.PatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch) {
    throw Error(where + ": fontconfig's match has no file");
  }
  // fontconfig always answers with something; only the family asked for is taken.
  FcChar8* got = nullptr;
  for (int i = 0; fc.PatternGetString(match.get(), FC_FAMILY, i, &got) == FcResultMatch; ++i) {
    if (fc.StrCmpIgnoreCase(got, wanted) == 0) return str(file);
  }
  const std::string nearest =
      fc.PatternGetString(match.get(), FC_FAMILY, 0, &got) == FcResultMatch ? str(got) : "?";
  throw EnvironmentError(where + ": not installed (fontconfig's nearest is '" + nearest + "', " +
                         str(file) +
                         "); the default font comes with the Debian package fonts-dejavu-core");
}

}  // namespace parksim
