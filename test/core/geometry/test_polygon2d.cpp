#include <cmath>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/polygon2d.h"

namespace brick_stack_sim {
namespace {

using V = Eigen::Vector2d;

TEST(Polygon2d, HullOfASquareWithInnerAndEdgePoints) {
  // Corners, a point inside, a point on an edge and a duplicate corner.
  const Polygon2d hull =
      convexHull({V(0, 0), V(2, 0), V(2, 1), V(0, 1), V(1, 0.5), V(1, 0), V(2, 1)});
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_DOUBLE_EQ(area(hull), 2.0);  // counter-clockwise: positive
  EXPECT_TRUE(centroid(hull).isApprox(V(1, 0.5)));
}

TEST(Polygon2d, HullKeepsSubMillimetreCorners) {
  // A contact patch 0.2 mm across: Bullet's 2D Graham scan merges points this
  // close to its anchor (FLT_EPSILON on the squared distance); ours must not.
  const double e = 2e-4;
  const Polygon2d hull =
      convexHull({V(0.1, 0.1), V(0.1 + e, 0.1), V(0.1 + e, 0.1 + e), V(0.1, 0.1 + e)});
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_NEAR(area(hull), e * e, 1e-9 * e * e);
}

TEST(Polygon2d, DegenerateHulls) {
  EXPECT_EQ(convexHull({V(1, 1)}).size(), 1u);
  EXPECT_EQ(convexHull({V(1, 1), V(1, 1)}).size(), 1u);
  const Polygon2d segment = convexHull({V(0, 0), V(1, 1), V(2, 2), V(0.5, 0.5)});
  ASSERT_EQ(segment.size(), 2u);
  EXPECT_EQ(area(segment), 0.0);
  EXPECT_TRUE(centroid(segment).isApprox(V(1, 1)));
}

TEST(Polygon2d, SignedDistanceInsideAndOutside) {
  const Polygon2d square = convexHull({V(0, 0), V(2, 0), V(2, 2), V(0, 2)});
  EXPECT_DOUBLE_EQ(signedDistance(square, V(1, 1)), 1.0);
  EXPECT_DOUBLE_EQ(signedDistance(square, V(0.5, 1)), 0.5);
  EXPECT_DOUBLE_EQ(signedDistance(square, V(3, 1)), -1.0);
  EXPECT_DOUBLE_EQ(signedDistance(square, V(3, 3)), -std::sqrt(2.0));  // nearest a corner
  EXPECT_DOUBLE_EQ(signedDistance(square, V(2, 1)), 0.0);
  EXPECT_TRUE(contains(square, V(2, 1)));
  EXPECT_FALSE(contains(square, V(2.001, 1)));
  EXPECT_TRUE(contains(square, V(2.001, 1), 0.002));
}

TEST(Polygon2d, PointAndEdgeSupportNothing) {
  // The thesis inflated 1- and 2-point patches into small diamonds, which can
  // call a brick balanced on an edge stable. A degenerate hull has no inside.
  const Polygon2d point{V(1, 1)};
  const Polygon2d edge = convexHull({V(0, 0), V(2, 0)});
  EXPECT_DOUBLE_EQ(signedDistance(point, V(1, 1)), 0.0);
  EXPECT_DOUBLE_EQ(signedDistance(point, V(1, 2)), -1.0);
  EXPECT_DOUBLE_EQ(signedDistance(edge, V(1, 0)), 0.0);
  EXPECT_DOUBLE_EQ(signedDistance(edge, V(1, 0.5)), -0.5);
  EXPECT_DOUBLE_EQ(signedDistance(edge, V(3, 0)), -1.0);
  EXPECT_LE(signedDistance(edge, V(0.3, 0)), 0.0);
}

TEST(Polygon2d, IntersectionOfCrossedRectangles) {
  // Two KAPLA footprints crossing at right angles overlap in a W x W square.
  const double l = 0.117 / 2, w = 0.0234 / 2;
  const Polygon2d along_x = convexHull({V(-l, -w), V(l, -w), V(l, w), V(-l, w)});
  const Polygon2d along_y = convexHull({V(-w, -l), V(w, -l), V(w, l), V(-w, l)});
  const Polygon2d overlap = intersectConvex(along_x, along_y);
  ASSERT_EQ(overlap.size(), 4u);
  EXPECT_NEAR(area(overlap), 4 * w * w, 1e-15);
  // Disjoint and edge-touching rectangles have no overlap with area.
  const Polygon2d far = convexHull({V(1, 1), V(2, 1), V(2, 2), V(1, 2)});
  EXPECT_TRUE(intersectConvex(along_x, far).empty());
  const Polygon2d touching = convexHull({V(l, -w), V(l + 1, -w), V(l + 1, w), V(l, w)});
  EXPECT_TRUE(intersectConvex(along_x, touching).empty());
}

}  // namespace
}  // namespace brick_stack_sim
