#include "brick_stack_sim/teleop/placement_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brick_stack_sim/core/geometry/polygon2d.h"

namespace brick_stack_sim {
namespace teleop {

namespace {

/// The outline of `box` seen from above [m]; exact for any orientation since
/// the projection of a box is the hull of its projected corners.
Polygon2d footprint(const OrientedBox& box) {
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector3d& corner : corners(box)) points.push_back(corner.head<2>());
  return convexHull(points);
}

}  // namespace

double supportTopUnder(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks) {
  const Polygon2d ghost_footprint = footprint(ghost);
  const double ghost_centre_z = ghost.pose.translation().z();
  double top = kTableTop;
  for (const OrientedBox& brick : bricks) {
    // The hull of a NaN corner is undefined: such a brick supports nothing.
    if (!brick.pose.matrix().allFinite() || !brick.half_extents.allFinite()) continue;
    const double brick_top = bounds(brick).max().z();
    if (brick_top <= top || brick_top > ghost_centre_z) continue;
    if (area(intersectConvex(ghost_footprint, footprint(brick))) < kMinFootprintOverlap) continue;
    top = brick_top;
  }
  return top;
}

Eigen::Isometry3d restingPose(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks) {
  Eigen::Isometry3d pose = ghost.pose;
  pose.translation().z() += supportTopUnder(ghost, bricks) - bounds(ghost).min().z();
  return pose;
}

double lowestCentreZ(const Eigen::Vector3d& half_extents, const Eigen::Matrix3d& rotation) {
  // The box's extent along world z: each of its axes' z component times its
  // half extent.
  return kTableTop + rotation.row(2).cwiseAbs().dot(half_extents.cwiseAbs());
}

Eigen::Vector3d besideBricks(const std::vector<OrientedBox>& bricks,
                             const Eigen::Vector3d& half_extents, const Eigen::Vector3d& fallback) {
  Eigen::AlignedBox3d around;
  for (const OrientedBox& brick : bricks)
    if (brick.pose.matrix().allFinite() && brick.half_extents.allFinite())
      around.extend(bounds(brick));
  if (around.isEmpty()) return fallback;
  const Eigen::Vector3d half = half_extents.cwiseAbs();
  return Eigen::Vector3d(around.max().x() + half.x() + half.maxCoeff(),
                         0.5 * (around.min().y() + around.max().y()), kTableTop + half.z());
}

int nearestIndex(const Eigen::Vector3d& point, const std::vector<Eigen::Vector3d>& centres) {
  int nearest = -1;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const double distance = (centres[i] - point).squaredNorm();
    if (distance < nearest_distance) {
      nearest_distance = distance;
      nearest = static_cast<int>(i);
    }
  }
  return nearest;
}

}  // namespace teleop
}  // namespace brick_stack_sim
