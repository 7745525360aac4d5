#include "brick_stack_sim/core/types/table_solid.h"

namespace brick_stack_sim {

Eigen::Vector3d tableHalfExtents(const TableOptions& table) {
  return Eigen::Vector3d(table.size.x() / 2, table.size.y() / 2, table.thickness / 2);
}

ConvexSolid tableSolid(const TableOptions& table) { return boxSolid(tableHalfExtents(table)); }

Eigen::Isometry3d tablePose(const TableOptions& table) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().z() = -table.thickness / 2;
  return pose;
}

}  // namespace brick_stack_sim
