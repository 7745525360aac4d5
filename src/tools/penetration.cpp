#include "brick_stack_sim/tools/penetration.h"

#include <algorithm>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/types/table_solid.h"

namespace brick_stack_sim {

double deepestPenetration(const std::vector<BrickSnapshot>& bricks, const TableOptions& table) {
  const ConvexSolid slab = tableSolid(table);
  const PlacedSolid placed_slab{tablePose(table), &slab};
  const Eigen::AlignedBox3d slab_bounds = bounds(placed_slab);

  // A snapshot without a solid is a box of its size.
  std::vector<ConvexSolid> boxes;
  boxes.reserve(bricks.size());
  std::vector<PlacedSolid> solids;
  std::vector<Eigen::AlignedBox3d> extents;
  double deepest = 0.0;
  for (const BrickSnapshot& b : bricks) {
    if (!b.solid) boxes.push_back(boxSolid(0.5 * b.size));
    solids.push_back(PlacedSolid{b.pose, b.solid ? b.solid.get() : &boxes.back()});
    extents.push_back(bounds(solids.back()));
    if (extents.back().intersects(slab_bounds))
      deepest = std::max(deepest, -separation(solids.back(), placed_slab));
    deepest = std::max(deepest, -table.height - extents.back().min().z());
  }
  for (std::size_t i = 0; i < solids.size(); ++i)
    for (std::size_t j = i + 1; j < solids.size(); ++j)
      if (extents[i].intersects(extents[j]))
        deepest = std::max(deepest, -separation(solids[i], solids[j]));
  return deepest;
}

}  // namespace brick_stack_sim
