#pragma once

#include <vector>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

/// The deepest overlap in `bricks` [m], 0 when nothing overlaps: of two
/// bricks, of a brick into the table (the slab of `table`'s top face and
/// thickness, its top at z = 0) or of a brick below the floor (`table`'s
/// height under the top). Each overlap is the separating-axis depth of the
/// solids (separation()), so a plank that hangs over the table's edge,
/// tilted below the top beside the slab, overlaps nothing.
double deepestPenetration(const std::vector<BrickSnapshot>& bricks, const TableOptions& table);

}  // namespace brick_stack_sim
