#pragma once
// A success matrix: one cell per (row, column) coloured from red (0 %) through yellow to green
// (100 %), with "k/n" and the percentage written in it; built as a Scene in pixel units.

#include <string>
#include <vector>

#include "parksim/renders/scene/Scene.h"
#include "parksim/renders/scene/SceneStyle.h"

namespace parksim {

struct SuccessCell {
  int successes = 0;
  int total = 0;  ///< 0: no episodes, drawn grey
};

/// cells[r][c] for rows x columns; every row as long as `columns`. Throws Error otherwise.
Scene buildSuccessMatrix(const std::vector<std::string>& rows,
                         const std::vector<std::string>& columns,
                         const std::vector<std::vector<SuccessCell>>& cells,
                         const std::string& title, int width_px, int height_px,
                         const SceneStyle& style);

}  // namespace parksim
