// Load splits checked against statics by hand: force balance (the shares add
// up to the load), moment balance (their moments add up to the load's) and
// every point of action inside its own patch.
#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/load_distribution.h"

namespace brick_stack_sim {
namespace {

using V = Eigen::Vector2d;

Polygon2d square(const V& centre, double half) {
  return convexHull({centre + V(-half, -half), centre + V(half, -half), centre + V(half, half),
                     centre + V(-half, half)});
}

void expectBalanced(double mass, const V& point, const std::vector<Polygon2d>& patches,
                    const std::vector<LoadShare>& shares) {
  ASSERT_EQ(shares.size(), patches.size());
  double total = 0.0;
  V moment = V::Zero();
  for (std::size_t i = 0; i < shares.size(); ++i) {
    EXPECT_GE(shares[i].mass, 0.0) << i;
    total += shares[i].mass;
    moment += shares[i].mass * shares[i].point;
    if (shares[i].mass > 0.0) {
      EXPECT_TRUE(contains(patches[i], shares[i].point, 1e-12)) << i;
    }
  }
  EXPECT_NEAR(total, mass, 1e-12);
  EXPECT_NEAR(moment.x(), mass * point.x(), 1e-12);
  EXPECT_NEAR(moment.y(), mass * point.y(), 1e-12);
}

TEST(LoadDistribution, OneSupporterTakesAllAtTheLoadsProjection) {
  const std::vector<Polygon2d> patches{square(V(0, 0), 0.01)};
  std::vector<LoadShare> shares;
  EXPECT_EQ(distributeLoad(2.0, V(0.004, -0.003), patches, &shares),
            LoadSplitRule::kSingleSupporter);
  ASSERT_EQ(shares.size(), 1u);
  EXPECT_DOUBLE_EQ(shares[0].mass, 2.0);
  EXPECT_TRUE(shares[0].point.isApprox(V(0.004, -0.003)));
  EXPECT_EQ(distributeLoad(2.0, V(0.02, 0), patches, &shares), LoadSplitRule::kUnsupported);
  EXPECT_TRUE(shares.empty());
}

TEST(LoadDistribution, TwoSupportersSplitByTheLeverRule) {
  // Patch centres at x = -0.04 and +0.04; a 3 kg load at x = +0.01, y = +0.002.
  // Lever rule: the far supporter takes (0.04 - 0.01) / 0.08 = 3/8 of it.
  const std::vector<Polygon2d> patches{square(V(-0.04, 0), 0.01), square(V(0.04, 0), 0.01)};
  std::vector<LoadShare> shares;
  ASSERT_EQ(distributeLoad(3.0, V(0.01, 0.002), patches, &shares), LoadSplitRule::kLeverRule);
  EXPECT_NEAR(shares[0].mass, 3.0 * 3.0 / 8.0, 1e-12);
  EXPECT_NEAR(shares[1].mass, 3.0 * 5.0 / 8.0, 1e-12);
  // Both act at their patch centre, moved across the centre line with the load.
  EXPECT_TRUE(shares[0].point.isApprox(V(-0.04, 0.002)));
  EXPECT_TRUE(shares[1].point.isApprox(V(0.04, 0.002)));
  expectBalanced(3.0, V(0.01, 0.002), patches, shares);
}

TEST(LoadDistribution, FourStackLoadsStayOverTheirColumns) {
  // The trap of the thesis's equation 10: a brick lying across two others
  // hands each of them half its weight at the crossing, not at its own centre.
  const double s = (0.117 - 0.0234) / 2, w = 0.0234 / 2;
  const std::vector<Polygon2d> patches{square(V(-s, -s), w), square(V(-s, s), w)};
  std::vector<LoadShare> shares;
  ASSERT_EQ(distributeLoad(0.0119, V(-s, 0), patches, &shares), LoadSplitRule::kLeverRule);
  EXPECT_NEAR(shares[0].mass, 0.0119 / 2, 1e-15);
  EXPECT_TRUE(shares[0].point.isApprox(V(-s, -s)));
  EXPECT_TRUE(shares[1].point.isApprox(V(-s, s)));
}

TEST(LoadDistribution, ThreeSupportersBalanceMomentsNotAnEqualSplit) {
  // Three patches in a row at x = -1, 0, 3 (m): an equal split acts at x = 2/3,
  // so a load at x = 0.5 needs unequal shares. Closest to equal with both
  // balances: f = (1/3 + d) with d solving the two constraints.
  const std::vector<Polygon2d> patches{square(V(-1, 0), 0.1), square(V(0, 0), 0.1),
                                       square(V(3, 0), 0.1)};
  std::vector<LoadShare> shares;
  ASSERT_EQ(distributeLoad(1.0, V(0.5, 0), patches, &shares), LoadSplitRule::kLeastNorm);
  expectBalanced(1.0, V(0.5, 0), patches, shares);
  // Least squares from (1/3, 1/3, 1/3) along the null-space-free direction:
  // corrections d = lambda * (1, x_i) with sum d = 0 and sum d x = 0.5 - 2/3.
  // sum x = 2, sum x^2 = 10: lambda0 * 3 + lambda1 * 2 = 0, lambda0 * 2 + lambda1 * 10 = -1/6.
  const double lambda1 = (-1.0 / 6.0) / (10.0 - 4.0 / 3.0), lambda0 = -2.0 * lambda1 / 3.0;
  const double x[3] = {-1, 0, 3};
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(shares[i].mass, 1.0 / 3.0 + lambda0 + lambda1 * x[i], 1e-12) << i;
}

TEST(LoadDistribution, ThreeSupportersDropOneThatWouldHaveToPull) {
  // Patches at x = -1, 0, 1 and a load at x = -0.9: closest to equal would be
  // f = 1/3 - 0.45 x, which pulls at x = 1. Without it, the lever rule between
  // -1 and 0 gives 0.9 and 0.1.
  const std::vector<Polygon2d> patches{square(V(-1, 0), 0.1), square(V(0, 0), 0.1),
                                       square(V(1, 0), 0.1)};
  std::vector<LoadShare> shares;
  EXPECT_EQ(distributeLoad(1.0, V(-0.9, 0), patches, &shares), LoadSplitRule::kLeastNorm);
  expectBalanced(1.0, V(-0.9, 0), patches, shares);
  EXPECT_NEAR(shares[0].mass, 0.9, 1e-12);
  EXPECT_NEAR(shares[1].mass, 0.1, 1e-12);
  EXPECT_NEAR(shares[2].mass, 0.0, 1e-12);
}

TEST(LoadDistribution, LoadBeyondACentreRestsOnItsOwnPatch) {
  // The load lies outside the segment between the centres (beyond the left
  // one) but inside the left patch: the left supporter carries it all.
  const std::vector<Polygon2d> patches{square(V(-1, 0), 0.1), square(V(1, 0), 0.1)};
  std::vector<LoadShare> shares;
  EXPECT_EQ(distributeLoad(1.0, V(-1.05, 0.099), patches, &shares),
            LoadSplitRule::kOnePatchCarries);
  expectBalanced(1.0, V(-1.05, 0.099), patches, shares);
  EXPECT_NEAR(shares[0].mass, 1.0, 1e-12);
}

TEST(LoadDistribution, NarrowPatchFallsBackToABalancedTriangle) {
  // The right patch is 2 cm wide in y: the lever rule would act 5 cm off its
  // centre line, outside it. The split over a triangle of patch corners still
  // balances force and moment with every point inside its patch.
  const Polygon2d narrow = convexHull({V(0.9, -0.01), V(1.1, -0.01), V(1.1, 0.01), V(0.9, 0.01)});
  const std::vector<Polygon2d> patches{square(V(-1, 0), 0.1), narrow};
  std::vector<LoadShare> shares;
  EXPECT_EQ(distributeLoad(1.0, V(0, 0.05), patches, &shares), LoadSplitRule::kHullTriangle);
  expectBalanced(1.0, V(0, 0.05), patches, shares);
}

TEST(LoadDistribution, OutsideEveryPatchCombinationIsUnsupported) {
  const std::vector<Polygon2d> patches{square(V(-1, 0), 0.1), square(V(1, 0), 0.1)};
  std::vector<LoadShare> shares;
  EXPECT_EQ(distributeLoad(1.0, V(0, 0.5), patches, &shares), LoadSplitRule::kUnsupported);
  EXPECT_EQ(distributeLoad(1.0, V(1.2, 0), patches, &shares), LoadSplitRule::kUnsupported);
}

}  // namespace
}  // namespace brick_stack_sim
