#include "brick_stack_sim/core/types/table_solid.h"

namespace brick_stack_sim {

ConvexSolid tableSolid(const TableOptions& table) {
  return boxSolid(Eigen::Vector3d(table.size.x() / 2, table.size.y() / 2, table.thickness / 2));
}

Eigen::Isometry3d tablePose(const TableOptions& table) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().z() = -table.thickness / 2;
  return pose;
}

}  // namespace brick_stack_sim
