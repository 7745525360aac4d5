#include "brick_stack_sim/core/geometry/box_geometry.h"

#include "brick_stack_sim/core/geometry/polygon2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace brick_stack_sim {

std::array<Eigen::Vector3d, 8> corners(const OrientedBox& box) {
  std::array<Eigen::Vector3d, 8> result;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    result[i] = box.pose * sign.cwiseProduct(box.half_extents).eval();
  }
  return result;
}

Eigen::AlignedBox3d bounds(const OrientedBox& box) {
  Eigen::AlignedBox3d result;
  for (const Eigen::Vector3d& corner : corners(box)) result.extend(corner);
  return result;
}

double projectedRadius(const OrientedBox& box, const Eigen::Vector3d& axis) {
  const Eigen::Matrix3d& r = box.pose.linear();
  return box.half_extents.x() * std::abs(r.col(0).dot(axis)) +
         box.half_extents.y() * std::abs(r.col(1).dot(axis)) +
         box.half_extents.z() * std::abs(r.col(2).dot(axis));
}

Eigen::Vector3d nearestPointIn(const OrientedBox& box, const Eigen::Vector3d& point) {
  const Eigen::Vector3d local = box.pose.inverse() * point;
  return box.pose * local.cwiseMax(-box.half_extents).cwiseMin(box.half_extents);
}

double separation(const OrientedBox& a, const OrientedBox& b) {
  const Eigen::Vector3d offset = b.pose.translation() - a.pose.translation();
  const Eigen::Matrix3d& ra = a.pose.linear();
  const Eigen::Matrix3d& rb = b.pose.linear();
  double largest_gap = -std::numeric_limits<double>::infinity();
  auto test_axis = [&](const Eigen::Vector3d& axis) {
    const double gap =
        std::abs(offset.dot(axis)) - projectedRadius(a, axis) - projectedRadius(b, axis);
    largest_gap = std::max(largest_gap, gap);
  };
  for (int i = 0; i < 3; ++i) {
    test_axis(ra.col(i));
    test_axis(rb.col(i));
  }
  // Edge-edge axes; parallel edges give no new axis (their face axes cover them).
  constexpr double kParallel = 1e-9;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d axis = ra.col(i).cross(rb.col(j));
      const double length = axis.norm();
      if (length > kParallel) test_axis(axis / length);
    }
  }
  return largest_gap;
}

namespace {

/// The face of `box` whose outward normal points most along `direction`:
/// its unit normal and its four corners.
void faceToward(const OrientedBox& box, const Eigen::Vector3d& direction, Eigen::Vector3d* normal,
                std::array<Eigen::Vector3d, 4>* face) {
  const Eigen::Matrix3d& r = box.pose.linear();
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(r.col(i).dot(direction)) > std::abs(r.col(axis).dot(direction))) axis = i;
  const double sign = r.col(axis).dot(direction) >= 0.0 ? 1.0 : -1.0;
  *normal = sign * r.col(axis);
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Eigen::Vector3d centre = box.pose.translation() + *normal * box.half_extents[axis];
  const Eigen::Vector3d du = r.col(u) * box.half_extents[u], dv = r.col(v) * box.half_extents[v];
  *face = {centre - du - dv, centre + du - dv, centre + du + dv, centre - du + dv};
}

}  // namespace

bool flushContactPatch(const OrientedBox& lower, const OrientedBox& upper, double max_angle,
                       double max_gap, std::vector<Eigen::Vector3d>* patch,
                       Eigen::Vector3d* normal) {
  Eigen::Vector3d lower_normal, upper_normal;
  std::array<Eigen::Vector3d, 4> lower_face, upper_face;
  faceToward(lower, Eigen::Vector3d::UnitZ(), &lower_normal, &lower_face);
  faceToward(upper, -Eigen::Vector3d::UnitZ(), &upper_normal, &upper_face);
  if (lower_normal.dot(-upper_normal) < std::cos(max_angle)) return false;
  if (lower_normal.z() <= 0.0) return false;  // a face that looks down carries nothing
  // The faces must touch: a brick under a lintel or beside a neighbour has
  // parallel faces that overlap seen from above, on another plane.
  const Eigen::Vector3d upper_centre =
      0.25 * (upper_face[0] + upper_face[1] + upper_face[2] + upper_face[3]);
  if (std::abs(lower_normal.dot(upper_centre - lower_face[0])) > max_gap) return false;
  if (lower_normal.dot(upper.pose.translation() - lower.pose.translation()) <= 0.0) return false;
  std::vector<Eigen::Vector2d> lower_2d, upper_2d;
  for (const Eigen::Vector3d& c : lower_face) lower_2d.push_back(c.head<2>());
  for (const Eigen::Vector3d& c : upper_face) upper_2d.push_back(c.head<2>());
  const Polygon2d overlap = intersectConvex(convexHull(upper_2d), convexHull(lower_2d));
  if (overlap.empty()) return false;
  // Lift each corner onto the plane of the lower face.
  const Eigen::Vector3d& origin = lower_face[0];
  patch->clear();
  for (const Eigen::Vector2d& corner : overlap) {
    const double z = origin.z() - (lower_normal.x() * (corner.x() - origin.x()) +
                                   lower_normal.y() * (corner.y() - origin.y())) /
                                      lower_normal.z();
    patch->emplace_back(corner.x(), corner.y(), z);
  }
  if (normal) *normal = lower_normal;
  return true;
}

bool isRotation(const Eigen::Matrix3d& rotation, double tolerance) {
  if (!rotation.allFinite()) return false;
  const double orthonormality =
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm();
  return orthonormality <= tolerance && std::abs(rotation.determinant() - 1.0) <= tolerance;
}

}  // namespace brick_stack_sim
