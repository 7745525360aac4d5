#pragma once

#include <array>
#include <vector>

#include <Eigen/Geometry>

namespace brick_stack_sim {

/// An oriented box: centre and orientation in `pose`, half extents along its axes [m].
struct OrientedBox {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();
};

/// The eight corners of a box in world coordinates [m].
std::array<Eigen::Vector3d, 8> corners(const OrientedBox& box);

/// The axis-aligned bounds of a box [m].
Eigen::AlignedBox3d bounds(const OrientedBox& box);

/// Half the length of the box's projection on the unit `axis` [m].
double projectedRadius(const OrientedBox& box, const Eigen::Vector3d& axis);

/// The axis (0, 1, 2) of the face of `box` whose outward normal points most
/// along `direction`; `normal` receives that unit outward normal.
int faceAxisToward(const OrientedBox& box, const Eigen::Vector3d& direction,
                   Eigen::Vector3d* normal);

/// The point of `box` (inside or on it) nearest `point` [m].
Eigen::Vector3d nearestPointIn(const OrientedBox& box, const Eigen::Vector3d& point);

/// Separating-axis distance of two boxes [m]: the largest gap along any of the
/// 15 candidate axes. Positive: the boxes are apart (a lower bound of their
/// distance). Zero: they touch. Negative: they overlap, and its magnitude is the
/// depth along the axis of least penetration.
double separation(const OrientedBox& a, const OrientedBox& b);

/// The contact patch of `upper` resting flat on `lower`: when the downward
/// face of `upper` lies on the upward face of `lower` (parallel within
/// `max_angle` [rad], its centre within `max_gap` [m] of that face's plane)
/// and `upper` is the higher box, the overlap of the two faces seen from
/// above, lifted onto the lower face. Bullet's box-box clipper keeps only
/// penetrating points, so a brick tilted by a micro-radian reports half its
/// patch; resting flush, the whole overlap carries. `normal` (optional)
/// receives the lower face's (unit, towards `upper`): on an inclined brick
/// it is no longer vertical. False when the faces are not flush, not in
/// contact, or do not overlap.
bool flushContactPatch(const OrientedBox& lower, const OrientedBox& upper, double max_angle,
                       double max_gap, std::vector<Eigen::Vector3d>* patch,
                       Eigen::Vector3d* normal = nullptr);

/// Whether `rotation` is a proper rotation (orthonormal, determinant +1) within `tolerance`.
bool isRotation(const Eigen::Matrix3d& rotation, double tolerance = 1e-6);

}  // namespace brick_stack_sim
