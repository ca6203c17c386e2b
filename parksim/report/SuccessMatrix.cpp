#include "parksim/report/SuccessMatrix.h"

#include <algorithm>
#include <cstdio>

#include "parksim/core/io/Error.h"
#include "parksim/report/PlotCanvas.h"

namespace parksim {
namespace {

std::uint8_t mix(double a, double b, double t) {
  return static_cast<std::uint8_t>(std::clamp(a + (b - a) * t, 0.0, 255.0));
}

// Red at 0, yellow at 0.5, green at 1.
Rgba8 successColor(double rate) {
  if (rate < 0.5) {
    const double t = rate / 0.5;
    return rgb(mix(225, 245, t), mix(90, 215, t), mix(80, 90, t));
  }
  const double t = (rate - 0.5) / 0.5;
  return rgb(mix(245, 110, t), mix(215, 195, t), mix(90, 110, t));
}

}  // namespace

Scene buildSuccessMatrix(const std::vector<std::string>& rows,
                         const std::vector<std::string>& columns,
                         const std::vector<std::vector<SuccessCell>>& cells,
                         const std::string& title, int width_px, int height_px,
                         const SceneStyle& style) {
  if (cells.size() != rows.size()) throw Error("success matrix: one row of cells per row label");
  for (const std::vector<SuccessCell>& row : cells) {
    if (row.size() != columns.size()) {
      throw Error("success matrix: one cell per column label in every row");
    }
  }
  Scene scene;
  PlotCanvas c(scene, width_px, height_px);
  const double size = style.text_px;
  std::size_t longest = 1;
  for (const std::string& r : rows) longest = std::max(longest, r.size());
  const double left = std::min(0.45 * width_px, (0.62 * longest + 2.0) * size);
  const double right = width_px - 1.0 * size;
  const double top = 5.0 * size;
  const double bottom = height_px - 1.0 * size;
  c.text(title, 0.5 * width_px, 0.6 * size, static_cast<float>(1.2 * size), style.text,
         HAlign::kCenter, VAlign::kTop);
  const double cw = (right - left) / std::max<std::size_t>(1, columns.size());
  const double ch = (bottom - top) / std::max<std::size_t>(1, rows.size());
  for (std::size_t j = 0; j < columns.size(); ++j) {
    c.text(columns[j], left + (static_cast<double>(j) + 0.5) * cw, top - 0.5 * size,
           static_cast<float>(size), style.text, HAlign::kCenter, VAlign::kBottom);
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double y0 = top + static_cast<double>(i) * ch;
    c.text(rows[i], left - 0.6 * size, y0 + 0.5 * ch, static_cast<float>(size), style.text,
           HAlign::kRight, VAlign::kMiddle);
    for (std::size_t j = 0; j < columns.size(); ++j) {
      const double x0 = left + static_cast<double>(j) * cw;
      const SuccessCell& cell = cells[i][j];
      char text[64];
      Rgba8 fill = rgb(215, 215, 215);
      if (cell.total > 0) {
        const double rate = static_cast<double>(cell.successes) / cell.total;
        fill = successColor(rate);
        std::snprintf(text, sizeof text, "%.0f%% (%d/%d)", 100.0 * rate, cell.successes,
                      cell.total);
      } else {
        std::snprintf(text, sizeof text, "no episodes");
      }
      c.fillRect(x0, y0, x0 + cw, y0 + ch, fill, 0.0);
      c.outlineRect(x0, y0, x0 + cw, y0 + ch, rgb(255, 255, 255), 2.0f * style.grid_px, 0.003);
      c.text(text, x0 + 0.5 * cw, y0 + 0.5 * ch, static_cast<float>(size), style.text,
             HAlign::kCenter, VAlign::kMiddle);
    }
  }
  return scene;
}

}  // namespace parksim
