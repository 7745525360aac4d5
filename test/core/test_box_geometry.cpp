#include <cmath>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/box_geometry.h"

namespace brick_stack_sim {
namespace {

OrientedBox box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half, double yaw = 0.0) {
  OrientedBox b;
  b.pose.translation() = centre;
  b.pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  b.half_extents = half;
  return b;
}

TEST(BoxGeometry, CornersOfAnAxisAlignedBox) {
  const auto c = corners(box({1, 2, 3}, {0.5, 0.25, 0.125}));
  Eigen::Vector3d low = c[0], high = c[0];
  for (const auto& corner : c) {
    low = low.cwiseMin(corner);
    high = high.cwiseMax(corner);
  }
  EXPECT_TRUE(low.isApprox(Eigen::Vector3d(0.5, 1.75, 2.875)));
  EXPECT_TRUE(high.isApprox(Eigen::Vector3d(1.5, 2.25, 3.125)));
}

TEST(BoxGeometry, SeparationOfStackedBoxesIsTheGap) {
  const Eigen::Vector3d half(0.05, 0.01, 0.004);
  EXPECT_NEAR(separation(box({0, 0, 0}, half), box({0, 0, 0.008}, half)), 0.0, 1e-15);
  EXPECT_NEAR(separation(box({0, 0, 0}, half), box({0, 0, 0.010}, half)), 0.002, 1e-15);
  EXPECT_NEAR(separation(box({0, 0, 0}, half), box({0, 0, 0.006}, half)), -0.002, 1e-15);
}

TEST(BoxGeometry, CrossedBoxesOverlapByTheShallowestAxis) {
  const Eigen::Vector3d half(0.05, 0.01, 0.004);
  // Same centre, one turned 90 degrees: they overlap fully in z (0.008), and by
  // 0.02 along x and y; the least penetration is through z.
  EXPECT_NEAR(separation(box({0, 0, 0}, half), box({0, 0, 0}, half, M_PI / 2)), -0.008, 1e-12);
}

TEST(BoxGeometry, RotatedBoxBesideAnotherIsSeparatedAlongItsOwnAxis) {
  const Eigen::Vector3d half(0.05, 0.01, 0.004);
  // b is turned 45 degrees and placed so that along x it clears a by 1 mm:
  // its reach along x is (0.05 + 0.01) / sqrt(2).
  const double reach = (0.05 + 0.01) / std::sqrt(2.0);
  const double distance = 0.05 + reach + 0.001;
  const double gap = separation(box({0, 0, 0}, half), box({distance, 0, 0}, half, M_PI / 4));
  // The widest gap is along b's short axis v = (-1, 1) / sqrt(2): the centres
  // are distance / sqrt(2) apart along v, a reaches (0.05 + 0.01) / sqrt(2), b 0.01.
  EXPECT_NEAR(gap, distance / std::sqrt(2.0) - reach - 0.01, 1e-12);
  EXPECT_GT(gap, 0.001);
}

TEST(BoxGeometry, EdgeAxisSeparatesTiltedBoxes) {
  // Two cubes touching only edge to edge: each rotated 45 degrees about a
  // different axis. Face axes alone would report an overlap.
  OrientedBox a = box({0, 0, 0}, {0.5, 0.5, 0.5});
  a.pose.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  OrientedBox b = box({0, 0, 0}, {0.5, 0.5, 0.5});
  b.pose.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const double edge_reach = std::sqrt(0.5);  // half diagonal of a unit square face
  b.pose.translation() = Eigen::Vector3d(0, 0, 2 * edge_reach + 0.01);
  EXPECT_NEAR(separation(a, b), 0.01, 1e-12);
}

TEST(BoxGeometry, RotationCheck) {
  EXPECT_TRUE(isRotation(Eigen::Matrix3d::Identity()));
  EXPECT_TRUE(
      isRotation(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix()));
  EXPECT_FALSE(isRotation(2.0 * Eigen::Matrix3d::Identity()));
  EXPECT_FALSE(isRotation(-Eigen::Matrix3d::Identity()));  // a reflection
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(1, 1) = std::nan("");
  EXPECT_FALSE(isRotation(nan));
}

}  // namespace
}  // namespace brick_stack_sim
