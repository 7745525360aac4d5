#pragma once
// Leaning KAPLA planks laid out by hand for the statics tests: planks
// standing on their ends, tilted in the xz-plane, their thickness along the
// tilt. A plank tilted by `theta` [rad] from vertical has its length axis
// along (sin theta, 0, cos theta) and rests on the edge of its lower end.

#include <cmath>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace test {

inline Eigen::Vector3d kaplaHalfExtents() {
  return 0.5 * Eigen::Vector3d(kKaplaLength, kKaplaWidth, kKaplaThickness);
}

/// A table as a box whose top face is z = 0, wider than any test scene.
inline OrientedBox tableBox() {
  OrientedBox table;
  table.pose.translation() = Eigen::Vector3d(0.0, 0.0, -0.01);
  table.half_extents = Eigen::Vector3d(1.0, 1.0, 0.01);
  return table;
}

/// A KAPLA's orientation when its length leans by `theta` [rad] from
/// vertical towards +x (negative: towards -x).
inline Eigen::Matrix3d leaningRotation(double theta) {
  // The brick's length axis is its x, its thickness its z: turned by
  // theta - 90 degrees about y, x points up tilted towards +x.
  return Eigen::AngleAxisd(theta - M_PI / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

/// A plank leaning by `theta` towards +x whose upper inner edge (the one on
/// the +x side) is at x = `apex_x`, its lower inner edge on the table (z = 0).
inline Eigen::Isometry3d plankLeaningTowardsX(double theta, double apex_x) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = leaningRotation(theta);
  const double l = kKaplaLength, t = kKaplaThickness;
  pose.translation() = Eigen::Vector3d(apex_x - 0.5 * (t * std::cos(theta) + l * std::sin(theta)),
                                       0.0, 0.5 * (t * std::sin(theta) + l * std::cos(theta)));
  return pose;
}

/// The mirror image in the plane x = `mirror_x`.
inline Eigen::Isometry3d mirrored(const Eigen::Isometry3d& pose, double mirror_x = 0.0) {
  const Eigen::Matrix3d flip = Eigen::Vector3d(-1.0, 1.0, 1.0).asDiagonal();
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  // Mirror the box and turn it about y by 180 degrees: a proper rotation
  // with the same box.
  result.linear() = flip * pose.linear() * flip;
  result.translation() = pose.translation();
  result.translation().x() = 2.0 * mirror_x - pose.translation().x();
  return result;
}

/// The two planks of an inverted V (the card house element, thesis figure
/// 10), each leaning by `theta` [rad] from vertical, their upper inner edges
/// meeting at x = `apex_x`.
inline std::pair<Eigen::Isometry3d, Eigen::Isometry3d> vPlanks(double theta, double apex_x = 0.0) {
  const Eigen::Isometry3d left = plankLeaningTowardsX(theta, apex_x);
  return {left, mirrored(left, apex_x)};
}

/// Statics of the V (and of a plank against a frictionless wall): about the
/// lower edge, the plank's weight at (L sin - T cos) / 2 balances the
/// horizontal apex force H at height L cos, so H = m g (tan - T/L) / 2; the
/// table's friction must supply H <= mu m g. It stands while
/// tan(theta) <= 2 mu + T / L.
inline double vThresholdAngle(double mu) {
  return std::atan(2.0 * mu + kKaplaThickness / kKaplaLength);
}

/// A plank against a wall with friction `mu_wall` on a table with `mu`:
/// with the wall's friction F_w <= mu_wall H up at the top edge, moments
/// about the lower edge give H (cos + mu_wall sin) L = m g (L sin - T cos) / 2,
/// and the table needs H <= mu (m g - F_w), so it stands while
/// tan(theta) <= (2 mu + (T/L)(1 + mu mu_wall)) / (1 - mu mu_wall).
inline double ladderThresholdAngle(double mu, double mu_wall) {
  const double ratio = kKaplaThickness / kKaplaLength;
  return std::atan((2.0 * mu + ratio * (1.0 + mu * mu_wall)) / (1.0 - mu * mu_wall));
}

}  // namespace test
}  // namespace brick_stack_sim
