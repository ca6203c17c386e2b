#include "parksim/planner/search/SearchWindow.h"

#include <algorithm>

namespace parksim {

LotBounds searchWindow(const LotBounds& lot, const Pose2& a, const Pose2& b, double margin_m) {
  return {std::max(lot.x_min_m, std::min(a.x, b.x) - margin_m),
          std::max(lot.y_min_m, std::min(a.y, b.y) - margin_m),
          std::min(lot.x_max_m, std::max(a.x, b.x) + margin_m),
          std::min(lot.y_max_m, std::max(a.y, b.y) + margin_m)};
}

double firstMargin(const SearchWindowDef& def, const Pose2& a, const Pose2& b) {
  return std::max(def.min_margin_m, def.margin_fraction * positionDistance(a, b));
}

bool coversLot(const LotBounds& window, const LotBounds& lot) {
  return window.x_min_m <= lot.x_min_m && window.y_min_m <= lot.y_min_m &&
         window.x_max_m >= lot.x_max_m && window.y_max_m >= lot.y_max_m;
}

}  // namespace parksim
