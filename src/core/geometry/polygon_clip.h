#pragma once
// Clipping a face polygon by a plane: what box and convex contacts share.

#include <vector>

#include <Eigen/Core>

namespace brick_stack_sim {

/// Keeps the part of the convex `polygon` where `axis . (x - origin) <= limit`
/// (Sutherland-Hodgman against one plane) [m].
inline std::vector<Eigen::Vector3d> clipPolygon(const std::vector<Eigen::Vector3d>& polygon,
                                                const Eigen::Vector3d& axis,
                                                const Eigen::Vector3d& origin, double limit) {
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % polygon.size()];
    const double dp = axis.dot(p - origin) - limit, dq = axis.dot(q - origin) - limit;
    if (dp <= 0.0) kept.push_back(p);
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0))
      kept.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return kept;
}

}  // namespace brick_stack_sim
