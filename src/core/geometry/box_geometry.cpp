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

int faceAxisToward(const OrientedBox& box, const Eigen::Vector3d& direction,
                   Eigen::Vector3d* normal) {
  const Eigen::Matrix3d& r = box.pose.linear();
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(r.col(i).dot(direction)) > std::abs(r.col(axis).dot(direction))) axis = i;
  *normal = (r.col(axis).dot(direction) >= 0.0 ? 1.0 : -1.0) * r.col(axis);
  return axis;
}

namespace {

/// The four corners of the face of `box` across `axis` with outward
/// `normal`, in order.
std::array<Eigen::Vector3d, 4> faceCorners(const OrientedBox& box, int axis,
                                           const Eigen::Vector3d& normal) {
  const Eigen::Matrix3d& r = box.pose.linear();
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Eigen::Vector3d centre = box.pose.translation() + normal * box.half_extents[axis];
  const Eigen::Vector3d du = r.col(u) * box.half_extents[u], dv = r.col(v) * box.half_extents[v];
  return {centre - du - dv, centre + du - dv, centre + du + dv, centre - du + dv};
}

/// cos(`angle`), worked out again only when the angle changes: the
/// narrowphase asks flushContactPatch() of every pair within reach every
/// step, always with the same angle.
double cosineOf(double angle) {
  thread_local double last_angle = 0.0, last_cosine = 1.0;
  if (angle != last_angle) {
    last_cosine = std::cos(angle);
    last_angle = angle;
  }
  return last_cosine;
}

/// `face` seen from above.
std::array<Eigen::Vector2d, 4> fromAbove(const std::array<Eigen::Vector3d, 4>& face) {
  return {face[0].head<2>(), face[1].head<2>(), face[2].head<2>(), face[3].head<2>()};
}

}  // namespace

bool flushContactPatch(const OrientedBox& lower, const OrientedBox& upper, double max_angle,
                       double max_gap, std::vector<Eigen::Vector3d>* patch,
                       Eigen::Vector3d* normal) {
  // The cheap tests first: the narrowphase asks this of every pair of
  // boxes within reach, every step.
  Eigen::Vector3d lower_normal, upper_normal;
  const int lower_axis = faceAxisToward(lower, Eigen::Vector3d::UnitZ(), &lower_normal);
  const int upper_axis = faceAxisToward(upper, -Eigen::Vector3d::UnitZ(), &upper_normal);
  if (lower_normal.z() <= 0.0) return false;  // a face that looks down carries nothing
  if (lower_normal.dot(-upper_normal) < cosineOf(max_angle)) return false;
  // The faces must touch: a brick under a lintel or beside a neighbour has
  // parallel faces that overlap seen from above, on another plane.
  const Eigen::Vector3d lower_centre =
      lower.pose.translation() + lower_normal * lower.half_extents[lower_axis];
  const Eigen::Vector3d upper_centre =
      upper.pose.translation() + upper_normal * upper.half_extents[upper_axis];
  if (std::abs(lower_normal.dot(upper_centre - lower_centre)) > max_gap) return false;
  if (lower_normal.dot(upper.pose.translation() - lower.pose.translation()) <= 0.0) return false;
  const std::array<Eigen::Vector3d, 4> lower_face = faceCorners(lower, lower_axis, lower_normal);
  const std::array<Eigen::Vector3d, 4> upper_face = faceCorners(upper, upper_axis, upper_normal);
  InlinePolygon2d overlap;
  intersectQuadrilaterals(fromAbove(upper_face), fromAbove(lower_face), &overlap);
  if (overlap.empty()) return false;
  // Lift each corner onto the plane of the lower face.
  const Eigen::Vector3d& origin = lower_face[0];
  patch->clear();
  patch->reserve(overlap.size());
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
