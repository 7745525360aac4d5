#include <cmath>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/geometry/polygon2d.h"

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

namespace brick_stack_sim {
namespace {

constexpr double kHalfLength = 0.0585, kHalfWidth = 0.0117, kHalfThickness = 0.0039;

OrientedBox plank(const Eigen::Vector3d& centre, double yaw = 0.0) {
  OrientedBox b;
  b.pose.translation() = centre;
  b.pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  b.half_extents = Eigen::Vector3d(kHalfLength, kHalfWidth, kHalfThickness);
  return b;
}

double patchArea(const std::vector<Eigen::Vector3d>& patch) {
  std::vector<Eigen::Vector2d> flat;
  for (const Eigen::Vector3d& p : patch) flat.push_back(p.head<2>());
  return area(convexHull(flat));
}

TEST(FlushContactPatch, CrossedPlanksRestOnTheirSquareOverlap) {
  std::vector<Eigen::Vector3d> patch;
  const OrientedBox lower = plank({0, 0, kHalfThickness});
  const OrientedBox upper = plank({0, 0, 3 * kHalfThickness}, M_PI / 2);
  ASSERT_TRUE(flushContactPatch(lower, upper, 0.002, 1e-4, &patch));
  EXPECT_NEAR(patchArea(patch), 4 * kHalfWidth * kHalfWidth, 1e-12);
  for (const Eigen::Vector3d& corner : patch) EXPECT_NEAR(corner.z(), 2 * kHalfThickness, 1e-12);
}

TEST(FlushContactPatch, OnAnInclinedPlankTheNormalIsItsFaces) {
  // Both planks pitched by 35 degrees, the upper one lying flush on the
  // lower's top face: the patch carries along that face's normal, which is
  // 35 degrees from vertical (a brick placed there slides unless friction
  // holds it, which a vertical normal would hide).
  const Eigen::Matrix3d pitch =
      Eigen::AngleAxisd(-35.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  OrientedBox lower = plank({0, 0, 0.05});
  lower.pose.linear() = pitch;
  OrientedBox upper = lower;
  upper.pose.translation() += 2.0 * kHalfThickness * pitch.col(2) + 0.01 * pitch.col(0);
  std::vector<Eigen::Vector3d> patch;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  ASSERT_TRUE(flushContactPatch(lower, upper, 0.002, 1e-4, &patch, &normal));
  EXPECT_TRUE(normal.isApprox(pitch.col(2), 1e-12)) << normal.transpose();
  EXPECT_NEAR(std::acos(normal.z()), 35.0 * M_PI / 180.0, 1e-12);
}

TEST(FlushContactPatch, TiltedGappedOrMisplacedFacesAreNoPatch) {
  std::vector<Eigen::Vector3d> patch;
  const OrientedBox lower = plank({0, 0, kHalfThickness});
  // Tilted by 10 mrad about x: not flush within 2 mrad.
  OrientedBox tilted = plank({0, 0, 3 * kHalfThickness}, M_PI / 2);
  tilted.pose.linear() = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitX()) * tilted.pose.linear();
  EXPECT_FALSE(flushContactPatch(lower, tilted, 0.002, 1e-4, &patch));
  // Hovering 1 mm above: parallel, overlapping from above, but not touching.
  EXPECT_FALSE(
      flushContactPatch(lower, plank({0, 0, 3 * kHalfThickness + 1e-3}), 0.002, 1e-4, &patch));
  // Under a lintel: the "upper" box is the lower one; it carries nothing.
  EXPECT_FALSE(flushContactPatch(plank({0, 0, 3 * kHalfThickness}), lower, 0.002, 1e-4, &patch));
  // Beside a neighbour of the same height, sunk into it by 0.05 mm sideways:
  // the faces overlap seen from above, but 7.8 mm apart in height.
  EXPECT_FALSE(flushContactPatch(lower, plank({0, 2 * kHalfWidth - 5e-5, kHalfThickness}), 0.002,
                                 1e-4, &patch));
}

}  // namespace
}  // namespace brick_stack_sim
