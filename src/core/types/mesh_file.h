#pragma once
// Meshes of URDF brick types, read through Assimp: only their vertices
// matter, since a brick is the convex hull of its mesh.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// A mesh with more vertices than this is refused: its hull would cost
/// seconds at start-up, and a brick needs no such detail.
constexpr std::size_t kMaxMeshVertices = 100000;

/// The vertices of every mesh in the file at `path` (STL, OBJ, DAE and the
/// other formats Assimp reads), node transforms applied, each scaled by
/// `scale` [m per file unit]. An error saying why when the file does not
/// load, has no vertices, has too many, or a vertex is not finite.
Status readMeshVertices(const std::string& path, const Eigen::Vector3d& scale,
                        std::vector<Eigen::Vector3d>* vertices);

/// The file a URDF mesh `filename` names: `file://` and absolute paths as
/// they are, a relative path under `base_directory`, and
/// `package://name/rest` under the directory of package `name` found on
/// ROS_PACKAGE_PATH (a directory on it, or one level under it called
/// `name`, whose package.xml names it). An error when no package of that name is found.
Status resolveMeshPath(const std::string& filename, const std::string& base_directory,
                       std::string* path);

}  // namespace brick_stack_sim
