#pragma once
// The cells of a Hybrid A* search (HybridAStar.h, TimeAStar.h): which (x, y, heading) cell a pose
// falls in, over a rectangular window. Coarse everywhere; once the fine zone is switched on,
// finer within its radius of a source (the start, or the goal searching backwards), where a
// tight slot needs smaller moves. Fine cells are numbered after every coarse one, so a coarse
// and a fine cell never share a key.

#include <cstdint>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"

namespace parksim {

/// One resolution of the cells.
struct CellSize {
  double cell_m = 0.0;   ///< (x, y) cell side, m; positive
  int heading_bins = 0;  ///< heading cells over a full turn; positive
};

class SearchCells {
 public:
  SearchCells() = default;
  /// Cells over `window`, the fine zone off. `fine_zone_m` <= 0: never fine.
  SearchCells(const LotBounds& window, CellSize coarse, CellSize fine, double fine_zone_m,
              std::vector<Pose2> sources);

  /// Switches the fine zone on (the cells' keys change within it).
  void enableFineZone() { fine_on_ = true; }
  /// A new fine resolution (a finer level after a coarser one ran dry).
  void setFine(CellSize fine) { fine_ = fine; }

  bool inFineZone(const Pose2& p) const;
  std::int64_t key(const Pose2& p) const;

  double fineZone_m() const { return fine_zone_m_; }
  double width_m() const { return width_m_; }
  double height_m() const { return height_m_; }
  const std::vector<Pose2>& sources() const { return sources_; }

 private:
  double x_min_m_ = 0.0;
  double y_min_m_ = 0.0;
  double width_m_ = 0.0;
  double height_m_ = 0.0;
  CellSize coarse_;
  CellSize fine_;
  double fine_zone_m_ = 0.0;
  std::vector<Pose2> sources_;
  bool fine_on_ = false;
  std::int64_t coarse_cells_ = 0;  // fine keys start here
};

}  // namespace parksim
