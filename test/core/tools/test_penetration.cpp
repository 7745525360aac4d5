// The benchmark's penetration: the separating-axis depth of what overlaps,
// checked on planks placed by hand where the depth is known exactly, and on
// a plank over the table's edge that overlaps nothing though part of it is
// below the top.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/tools/penetration.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaThickness;
using test::kKaplaWidth;

constexpr double kHalfThickness = 0.5 * kKaplaThickness;

/// A plank lying flat, its long side along x, its centre at `centre` [m].
BrickSnapshot plankAt(const Eigen::Vector3d& centre) {
  BrickSnapshot plank;
  plank.size = Eigen::Vector3d(kKaplaLength, kKaplaWidth, kKaplaThickness);
  plank.pose.translation() = centre;
  return plank;
}

TEST(Penetration, APlankLyingOnTheTableOverlapsNothing) {
  const TableOptions table;
  EXPECT_EQ(deepestPenetration({plankAt({0.1, 0.0, kHalfThickness})}, table), 0.0);
}

TEST(Penetration, APlankSunkIntoTheTopOverlapsItByHowFarItSank) {
  const TableOptions table;
  const double sunk = 0.002;
  EXPECT_NEAR(deepestPenetration({plankAt({0.1, 0.0, kHalfThickness - sunk})}, table), sunk, 1e-12);
}

TEST(Penetration, APlankTiltedOverTheEdgeAboveItOverlapsNothing) {
  // Its centre 2 cm inside the edge at x = size.x / 2, tilted 10 degrees so
  // that its outer end dips about 7 mm below the top, beside the slab; its
  // bottom face passes 0.1 mm above the edge. Counting whatever lies below
  // the top as in the table would call that 7 mm deep.
  const TableOptions table;
  const double edge = table.size.x() / 2, tilt = 10.0 * M_PI / 180.0, gap = 1e-4;
  BrickSnapshot plank = plankAt(Eigen::Vector3d::Zero());
  plank.pose.linear() = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const double centre_x = edge - 0.02;
  // Along the bottom face from its centre to above the edge, then up.
  const double bottom_x = centre_x - kHalfThickness * std::sin(tilt);
  const double along = (edge - bottom_x) / std::cos(tilt);
  const double centre_z = gap + kHalfThickness * std::cos(tilt) + along * std::sin(tilt);
  plank.pose.translation() = Eigen::Vector3d(centre_x, 0.0, centre_z);
  const Eigen::Vector3d outer_bottom =
      plank.pose * Eigen::Vector3d(kKaplaLength / 2, 0.0, -kHalfThickness);
  ASSERT_LT(outer_bottom.z(), -0.006);  // the case the old count got wrong
  EXPECT_EQ(deepestPenetration({plank}, table), 0.0);
  // Lowered by 1 mm, it sinks into the edge: the depth across the face
  // that separates best, no more than the drop.
  plank.pose.translation().z() -= 0.001 + gap;
  const double depth = deepestPenetration({plank}, table);
  EXPECT_GT(depth, 0.0);
  EXPECT_LE(depth, 0.001 + 1e-12);
}

TEST(Penetration, APlankBesideTheTableThatSinksIntoItsSideOverlapsIt) {
  // Its centre is off the table's footprint: only the solids can tell.
  const TableOptions table;
  const double into = 0.003;
  BrickSnapshot plank =
      plankAt({table.size.x() / 2 + kKaplaLength / 2 - into, 0.0, -table.thickness / 2});
  plank.fell_off = true;
  EXPECT_NEAR(deepestPenetration({plank}, table), into, 1e-12);
}

TEST(Penetration, APlankBelowTheFloorOverlapsItByHowFarItIsBelow) {
  const TableOptions table;
  const double below = 0.001;
  EXPECT_NEAR(
      deepestPenetration({plankAt({2.0, 0.0, -table.height + kHalfThickness - below})}, table),
      below, 1e-12);
}

TEST(Penetration, TwoPlanksCrossedOneSunkIntoTheOtherOverlapByTheDepth) {
  const TableOptions table;
  const double sunk = 0.0015;
  BrickSnapshot lower = plankAt({0.0, 0.0, kHalfThickness});
  BrickSnapshot upper = plankAt({0.0, 0.0, 3.0 * kHalfThickness - sunk});
  upper.pose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_NEAR(deepestPenetration({lower, upper}, table), sunk, 1e-12);
  upper.pose.translation().z() += sunk;
  EXPECT_NEAR(deepestPenetration({lower, upper}, table), 0.0, 1e-12);
}

}  // namespace
}  // namespace brick_stack_sim
