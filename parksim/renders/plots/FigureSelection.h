#pragma once
// Which of the study's figures to write: `--figures none|all|LIST` on `parksim run` and
// `parksim render`, FigureDef::figures in the library.

#include <array>
#include <bitset>
#include <string>
#include <string_view>

namespace parksim {

/// The figures writeFigures can write, in the order it writes them (Figures.h). "plan" stands
/// for every plan_<name>.png.
inline constexpr std::array<std::string_view, 7> kFigureNames = {
    "lot_map", "steering", "cspace_slice", "cspace_stack", "plan", "tracking_error", "lot_3d"};

/// A subset of kFigureNames.
struct FigureSelection {
  std::bitset<kFigureNames.size()> chosen;  ///< bit i: kFigureNames[i]

  static FigureSelection all() { return {std::bitset<kFigureNames.size()>().set()}; }
  static FigureSelection none() { return {}; }
  /// "all", "none", or names from kFigureNames separated by commas (spaces around a name are
  /// ignored; a repeated name counts once; "all" and "none" may appear in a list too). Throws
  /// Error with a one-line message naming the unknown name and listing the valid ones.
  static FigureSelection parse(std::string_view text);

  /// Whether the figure `name` is chosen: a name from kFigureNames, or plan_<anything> for
  /// "plan". False for any other name.
  bool contains(std::string_view name) const;
  bool empty() const { return chosen.none(); }
  /// "all", "none", or the chosen names in kFigureNames order, separated by commas; parse
  /// reads it back.
  std::string toString() const;
};

/// "lot_map, steering, ..." (kFigureNames), for messages and help texts.
std::string figureNameList();

}  // namespace parksim
