#include "parksim/renders/plots/FigureSelection.h"

#include <algorithm>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

std::string_view trimmed(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

std::string shown(std::string_view name) {
  constexpr std::size_t kMax = 40;
  return "'" + std::string(name.substr(0, kMax)) + (name.size() > kMax ? "...'" : "'");
}

}  // namespace

std::string figureNameList() {
  std::string list;
  for (std::string_view name : kFigureNames) {
    if (!list.empty()) list += ", ";
    list += name;
  }
  return list;
}

FigureSelection FigureSelection::parse(std::string_view text) {
  FigureSelection selection;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string_view name = trimmed(text.substr(begin, comma - begin));
    const auto* it = std::find(kFigureNames.begin(), kFigureNames.end(), name);
    if (it != kFigureNames.end()) {
      selection.chosen.set(static_cast<std::size_t>(it - kFigureNames.begin()));
    } else if (name == "all") {
      selection.chosen.set();
    } else if (name != "none") {
      throw Error(
          (name.empty() ? std::string("empty figure name") : "unknown figure " + shown(name)) +
          "; figures: all, none, or a comma-separated list of " + figureNameList());
    }
    if (comma == text.size()) break;
    begin = comma + 1;
  }
  return selection;
}

bool FigureSelection::contains(std::string_view name) const {
  if (name.starts_with("plan_")) name = "plan";
  const auto* it = std::find(kFigureNames.begin(), kFigureNames.end(), name);
  return it != kFigureNames.end() &&
         chosen.test(static_cast<std::size_t>(it - kFigureNames.begin()));
}

std::string FigureSelection::toString() const {
  if (chosen.all()) return "all";
  if (chosen.none()) return "none";
  std::string list;
  for (std::size_t i = 0; i < kFigureNames.size(); ++i) {
    if (!chosen.test(i)) continue;
    if (!list.empty()) list += ',';
    list += kFigureNames[i];
  }
  return list;
}

}  // namespace parksim
