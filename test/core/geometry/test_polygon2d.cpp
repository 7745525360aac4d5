#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

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

/// The corners of a w x h rectangle centred at `centre`, turned by `angle`
/// [rad], in the order a box's face lists them.
std::array<V, 4> rectangle(const V& centre, double w, double h, double angle) {
  const Eigen::Rotation2Dd turn(angle);
  return {centre + turn * V(-w / 2, -h / 2), centre + turn * V(w / 2, -h / 2),
          centre + turn * V(w / 2, h / 2), centre + turn * V(-w / 2, h / 2)};
}

Polygon2d asPolygon(const InlinePolygon2d& inline_polygon) {
  return Polygon2d(inline_polygon.begin(), inline_polygon.end());
}

TEST(Polygon2d, QuadrilateralOverlapHasTheExactArea) {
  // Axis-aligned rectangles overlap in the rectangle of their ranges; one
  // turned by 90 degrees about a shared centre, in a square of the short
  // side; one inside another, in itself.
  InlinePolygon2d overlap;
  intersectQuadrilaterals(rectangle(V(0, 0), 0.117, 0.0234, 0.0),
                          rectangle(V(0.05, 0.01), 0.117, 0.0234, 0.0), &overlap);
  EXPECT_NEAR(area(asPolygon(overlap)), (0.117 - 0.05) * (0.0234 - 0.01), 1e-15);
  intersectQuadrilaterals(rectangle(V(0.3, -0.2), 0.117, 0.0234, 0.4),
                          rectangle(V(0.3, -0.2), 0.117, 0.0234, 0.4 + M_PI / 2), &overlap);
  EXPECT_NEAR(area(asPolygon(overlap)), 0.0234 * 0.0234, 1e-15);
  intersectQuadrilaterals(rectangle(V(0, 0), 0.01, 0.01, 0.3), rectangle(V(0, 0), 0.2, 0.2, 1.1),
                          &overlap);
  EXPECT_NEAR(area(asPolygon(overlap)), 1e-4, 1e-16);
  // Apart, and sharing only an edge: no overlap with area.
  intersectQuadrilaterals(rectangle(V(0, 0), 0.1, 0.1, 0.0), rectangle(V(0.2, 0), 0.1, 0.1, 0.0),
                          &overlap);
  EXPECT_TRUE(overlap.empty());
  intersectQuadrilaterals(rectangle(V(0, 0), 0.1, 0.1, 0.0), rectangle(V(0.1, 0), 0.1, 0.1, 0.0),
                          &overlap);
  EXPECT_TRUE(overlap.empty());
}

TEST(Polygon2d, QuadrilateralOverlapEqualsTheGeneralClipToTheBit) {
  // The narrowphase's in-place clip must give the corners the general one
  // gives, to the last bit: a contact point that moved by rounding would
  // change every run. Faces of planks at random headings and offsets,
  // given clockwise and counter-clockwise, crossing and flush along edges.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.06, 0.06), angle(-M_PI, M_PI);
  int overlapping = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double heading = trial % 10 == 0 ? 0.0 : angle(random);
    std::array<V, 4> lower = rectangle(V(0, 0), 0.117, 0.0234, 0.0);
    std::array<V, 4> upper =
        rectangle(V(offset(random), trial % 7 == 0 ? 0.0 : offset(random)), 0.117, 0.0234, heading);
    if (trial % 2 == 0) std::swap(upper[1], upper[3]);  // clockwise
    InlinePolygon2d in_place;
    intersectQuadrilaterals(upper, lower, &in_place);
    const Polygon2d general = intersectConvex(convexHull({upper.begin(), upper.end()}),
                                              convexHull({lower.begin(), lower.end()}));
    ASSERT_EQ(in_place.size(), general.size()) << "trial " << trial;
    for (std::size_t i = 0; i < general.size(); ++i) {
      EXPECT_EQ(in_place[i].x(), general[i].x()) << "trial " << trial;
      EXPECT_EQ(in_place[i].y(), general[i].y()) << "trial " << trial;
    }
    overlapping += general.empty() ? 0 : 1;
  }
  // Most of them overlap, or the comparison says little.
  EXPECT_GT(overlapping, 1000);
}

}  // namespace
}  // namespace brick_stack_sim
