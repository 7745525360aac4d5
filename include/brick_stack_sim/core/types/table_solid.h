#pragma once

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

/// The table's top as a solid: a box of its top face and thickness [m],
/// centred on its own frame (what Bullet collides with).
ConvexSolid tableSolid(const TableOptions& table);

/// Where tableSolid() lies in the world: its top face at z = 0.
Eigen::Isometry3d tablePose(const TableOptions& table);

}  // namespace brick_stack_sim
