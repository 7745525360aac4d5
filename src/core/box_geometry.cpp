#include "brick_stack_sim/core/box_geometry.h"

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

namespace {

/// Half the length of the box's projection on the unit `axis`.
double projectedRadius(const OrientedBox& box, const Eigen::Vector3d& axis) {
  const Eigen::Matrix3d& r = box.pose.linear();
  return box.half_extents.x() * std::abs(r.col(0).dot(axis)) +
         box.half_extents.y() * std::abs(r.col(1).dot(axis)) +
         box.half_extents.z() * std::abs(r.col(2).dot(axis));
}

}  // namespace

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

bool isRotation(const Eigen::Matrix3d& rotation, double tolerance) {
  if (!rotation.allFinite()) return false;
  const double orthonormality =
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm();
  return orthonormality <= tolerance && std::abs(rotation.determinant() - 1.0) <= tolerance;
}

}  // namespace brick_stack_sim
