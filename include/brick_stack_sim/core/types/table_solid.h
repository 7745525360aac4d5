#pragma once

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

/// Half the table top's size along x and y and half its thickness [m]:
/// the box that tableSolid() is and that Bullet collides with.
Eigen::Vector3d tableHalfExtents(const TableOptions& table);

/// The table's top as a solid: a box of its top face and thickness [m],
/// centred on its own frame.
ConvexSolid tableSolid(const TableOptions& table);

/// Where tableSolid() lies in the world: its top face at z = 0.
Eigen::Isometry3d tablePose(const TableOptions& table);

}  // namespace brick_stack_sim
