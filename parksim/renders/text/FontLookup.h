#pragma once
// Finding a font file by family name through fontconfig, as desktop programs do, rather than by a
// path that differs between distributions.

#include <string>

namespace parksim {

/// The renderer's default text font (Debian package fonts-dejavu-core).
inline constexpr const char* kDefaultFontFamily = "DejaVu Sans Mono";

/// The file of the best outline font of `family`, a fontconfig pattern ("DejaVu Sans Mono",
/// "DejaVu Sans:bold"). Throws Error when fontconfig has no font of that family: its nearest
/// substitute would change every image with text, so none is taken silently.
std::string findFontFile(const std::string& family = kDefaultFontFamily);

}  // namespace parksim
