#include "parksim/core/geometry/CompoundShape.h"

#include "parksim/core/io/Error.h"

namespace parksim {

std::shared_ptr<const CompoundShape> CompoundShape::make(
    std::vector<std::vector<Eigen::Vector2d>> parts,
    std::vector<std::vector<Eigen::Vector2d>> rings) {
  if (parts.empty()) throw Error("compound shape: no parts");
  auto shape = std::make_shared<CompoundShape>();
  shape->bounds.reserve(parts.size());
  shape->extent.setEmpty();
  for (const std::vector<Eigen::Vector2d>& part : parts) {
    if (part.size() < 3) throw Error("compound shape: a part has fewer than 3 vertices");
    Eigen::AlignedBox2d box;
    box.setEmpty();
    for (const Eigen::Vector2d& p : part) box.extend(p);
    shape->bounds.push_back(box);
    shape->extent.extend(box);
  }
  shape->parts = std::move(parts);
  shape->rings = std::move(rings);
  return shape;
}

}  // namespace parksim
