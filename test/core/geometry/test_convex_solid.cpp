#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/geometry/polygon2d.h"

namespace brick_stack_sim {
namespace {

constexpr double kGap = 1e-7;

Eigen::Isometry3d at(const Eigen::Vector3d& translation,
                     const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = translation;
  return pose;
}

/// A table whose top face is z = 0.
const ConvexSolid& table() {
  static const ConvexSolid solid = boxSolid(Eigen::Vector3d(0.2, 0.2, 0.05));
  return solid;
}
PlacedSolid placedTable() { return {at(Eigen::Vector3d(0, 0, -0.05)), &table()}; }

Eigen::Isometry3d randomPose(std::mt19937* random, double spread) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(-spread, spread);
  Eigen::Quaterniond q(normal(*random), normal(*random), normal(*random), normal(*random));
  return at(Eigen::Vector3d(uniform(*random), uniform(*random), uniform(*random)),
            q.normalized().toRotationMatrix());
}

Eigen::Vector3d randomHalfExtents(std::mt19937* random) {
  std::uniform_real_distribution<double> uniform(0.01, 0.1);
  return Eigen::Vector3d(uniform(*random), uniform(*random), uniform(*random));
}

void expectSameBits(const std::vector<BoxContactFace>& got,
                    const std::vector<BoxContactFace>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_TRUE(got[i].normal == want[i].normal);
    ASSERT_EQ(got[i].points.size(), want[i].points.size());
    for (std::size_t j = 0; j < got[i].points.size(); ++j)
      EXPECT_TRUE(got[i].points[j] == want[i].points[j]);
  }
}

/// `b` moved along `normal` so that `a`'s lowest corner along it lies `offset` above b's plane.
Eigen::Isometry3d restingOn(const OrientedBox& b, const Eigen::Vector3d& normal,
                            const OrientedBox& a, double offset) {
  const double top = normal.dot(b.pose.translation()) + projectedRadius(b, normal);
  const double bottom = normal.dot(a.pose.translation()) - projectedRadius(a, normal);
  Eigen::Isometry3d pose = a.pose;
  pose.translation() += (top + offset - bottom) * normal;
  return pose;
}

TEST(ConvexSolid, BoxSolidsGiveTheBoxRoutinesBits) {
  std::mt19937 random(42);
  std::uniform_real_distribution<double> within(-0.5 * kGap, 0.5 * kGap);
  int touching = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d half_a = randomHalfExtents(&random), half_b = randomHalfExtents(&random);
    const ConvexSolid solid_a = boxSolid(half_a), solid_b = boxSolid(half_b);
    OrientedBox a{randomPose(&random, 0.1), half_a}, b{randomPose(&random, 0.1), half_b};
    // Half the trials rest a on a face of b, within the gap.
    if (trial % 2) {
      a.pose.translation() = b.pose.translation() + 0.2 * a.pose.translation();  // over b's face
      a.pose = restingOn(b, b.pose.linear().col(trial % 3), a, within(random));
    }
    const PlacedSolid pa{a.pose, &solid_a}, pb{b.pose, &solid_b};
    EXPECT_EQ(separation(pa, pb), separation(a, b));
    const std::vector<BoxContactFace> want = touchingContacts(a, b, kGap);
    touching += !want.empty();
    expectSameBits(touchingContacts(pa, pb, kGap), want);
    const Eigen::Vector3d point = randomPose(&random, 0.2).translation();
    EXPECT_TRUE(nearestPointIn(pa, point) == nearestPointIn(a, point));
    EXPECT_TRUE(bounds(pa).min() == bounds(a).min());
    EXPECT_TRUE(bounds(pa).max() == bounds(a).max());
  }
  EXPECT_GT(touching, 25);
}

TEST(ConvexSolid, StackedBoxSolidsGiveTheBoxFlushPatchBits) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI), shift(-0.05, 0.05);
  int flush = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d half_a = randomHalfExtents(&random), half_b = randomHalfExtents(&random);
    const ConvexSolid lower_solid = boxSolid(half_b), upper_solid = boxSolid(half_a);
    const Eigen::Matrix3d turn_b =
        Eigen::AngleAxisd(yaw(random), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d turn_a =
        Eigen::AngleAxisd(yaw(random), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const OrientedBox lower{at(Eigen::Vector3d(shift(random), shift(random), 0.0), turn_b), half_b};
    const OrientedBox upper{
        at(Eigen::Vector3d(shift(random), shift(random), half_b.z() + half_a.z()), turn_a), half_a};
    std::vector<Eigen::Vector3d> want, got;
    Eigen::Vector3d want_normal(9, 9, 9), got_normal(9, 9, 9);
    const bool expected = flushContactPatch(lower, upper, 1e-3, 1e-6, &want, &want_normal);
    flush += expected;
    EXPECT_EQ(
        flushContactPatch(PlacedSolid{lower.pose, &lower_solid},
                          PlacedSolid{upper.pose, &upper_solid}, 1e-3, 1e-6, &got, &got_normal),
        expected);
    EXPECT_TRUE(got == want);
    EXPECT_TRUE(got_normal == want_normal);
  }
  EXPECT_GT(flush, 30);
}

TEST(ConvexSolid, GeneralPathAgreesWithTheBoxPathOnBoxes) {
  // The same boxes as polyhedra (not marked as boxes) take the polyhedron routines.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> within(-0.5 * kGap, 0.5 * kGap);
  int touching = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d half_a = randomHalfExtents(&random), half_b = randomHalfExtents(&random);
    const ConvexSolid solid_a = polyhedronSolid(boxPolyhedron(half_a));
    const ConvexSolid solid_b = polyhedronSolid(boxPolyhedron(half_b));
    OrientedBox a{randomPose(&random, 0.1), half_a}, b{randomPose(&random, 0.1), half_b};
    a.pose.translation() = b.pose.translation() + 0.2 * a.pose.translation();
    a.pose = restingOn(b, -b.pose.linear().col(trial % 3), a, within(random));
    const PlacedSolid pa{a.pose, &solid_a}, pb{b.pose, &solid_b};
    EXPECT_NEAR(separation(pa, pb), separation(a, b), 1e-15);
    const std::vector<BoxContactFace> want = touchingContacts(a, b, kGap);
    const std::vector<BoxContactFace> got = touchingContacts(pa, pb, kGap);
    touching += !want.empty();
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_TRUE(got[i].normal.isApprox(want[i].normal, 1e-12));
      ASSERT_EQ(got[i].points.size(), want[i].points.size());
      for (const Eigen::Vector3d& p : got[i].points) {
        double nearest = 1.0;
        for (const Eigen::Vector3d& q : want[i].points) nearest = std::min(nearest, (p - q).norm());
        EXPECT_LT(nearest, 1e-12);
      }
    }
    const Eigen::Vector3d point = randomPose(&random, 0.2).translation();
    EXPECT_LT((nearestPointIn(pa, point) - nearestPointIn(a, point)).norm(), 1e-15);
  }
  EXPECT_GT(touching, 30);
}

ConvexSolid cylinder(int sides) { return polyhedronSolid(cylinderPolyhedron(0.03, 0.1, sides)); }

TEST(ConvexSolid, StandingCylinderTouchesTheTableWithItsWholeCap) {
  const ConvexSolid solid = cylinder(32);
  const PlacedSolid standing{at(Eigen::Vector3d(0.01, -0.02, 0.05)), &solid};
  const std::vector<BoxContactFace> faces = touchingContacts(standing, placedTable(), kGap);
  // From the table's top, once: the cylinder's cap is its flush twin.
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_TRUE(faces[0].normal.isApprox(Eigen::Vector3d::UnitZ()));
  ASSERT_EQ(faces[0].points.size(), 32u);
  for (const Eigen::Vector3d& p : faces[0].points) {
    EXPECT_NEAR(p.z(), 0.0, 1e-15);
    EXPECT_NEAR((p.head<2>() - Eigen::Vector2d(0.01, -0.02)).norm(), 0.03, 1e-15);
  }
  EXPECT_NEAR(separation(standing, placedTable()), 0.0, 1e-15);

  std::vector<Eigen::Vector3d> patch;
  Eigen::Vector3d normal;
  ASSERT_TRUE(flushContactPatch(placedTable(), standing, 1e-3, 1e-6, &patch, &normal));
  EXPECT_TRUE(normal.isApprox(Eigen::Vector3d::UnitZ()));
  std::vector<Eigen::Vector2d> flat;
  for (const Eigen::Vector3d& p : patch) {
    EXPECT_NEAR(p.z(), 0.0, 1e-15);
    flat.push_back(p.head<2>());
  }
  // The cap's 32 triangles of sides r at 2 pi / 32.
  EXPECT_NEAR(area(convexHull(flat)), 16.0 * 0.03 * 0.03 * std::sin(2.0 * M_PI / 32.0), 1e-15);
}

TEST(ConvexSolid, OverhangingCylinderIsClippedToTheTableEdge) {
  const ConvexSolid solid = cylinder(32);
  const PlacedSolid standing{at(Eigen::Vector3d(0.2, 0.0, 0.05)), &solid};
  const std::vector<BoxContactFace> faces = touchingContacts(standing, placedTable(), kGap);
  ASSERT_EQ(faces.size(), 1u);
  // Vertices 8 to 24 (angles 90 to 270 degrees) lie at x <= 0.2; the cuts
  // through x = 0.2 + gap fall on vertices 8 and 24 and merge with them.
  EXPECT_EQ(faces[0].points.size(), 17u);
  for (const Eigen::Vector3d& p : faces[0].points) EXPECT_LE(p.x(), 0.2 + kGap);
}

TEST(ConvexSolid, LyingCylinderTouchesAlongOneLine) {
  const ConvexSolid solid = cylinder(32);
  // Its axis along x; vertex 0 (angle 0, local +x) turns to -z: the lowest line.
  const PlacedSolid lying{
      at(Eigen::Vector3d(0.05, 0.03, 0.03),
         Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix()),
      &solid};
  const std::vector<BoxContactFace> faces = touchingContacts(lying, placedTable(), kGap);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_TRUE(faces[0].normal.isApprox(Eigen::Vector3d::UnitZ()));
  ASSERT_GE(faces[0].points.size(), 2u);
  double low = 1.0, high = -1.0;
  for (const Eigen::Vector3d& p : faces[0].points) {
    EXPECT_NEAR(p.y(), 0.03, 1e-9);
    EXPECT_NEAR(p.z(), 0.0, 1e-15);
    low = std::min(low, p.x());
    high = std::max(high, p.x());
  }
  EXPECT_NEAR(low, 0.0, 1e-9);  // the length 0.1 about x = 0.05
  EXPECT_NEAR(high, 0.1, 1e-9);
  EXPECT_NEAR(separation(lying, placedTable()), 0.0, 1e-15);
  std::vector<Eigen::Vector3d> patch;
  // Its faces next to the line lean by pi / 32: none lies flush.
  EXPECT_FALSE(flushContactPatch(placedTable(), lying, 1e-3, 1e-6, &patch));
}

TEST(ConvexSolid, RoofRidgeOnTheTableGivesTheRidgeEnds) {
  ConvexPolyhedron roof;
  ASSERT_TRUE(convexHull3d({{0, -0.05, 0},
                            {0, 0.05, 0},
                            {-0.02, -0.05, 0.03},
                            {-0.02, 0.05, 0.03},
                            {0.02, -0.05, 0.03},
                            {0.02, 0.05, 0.03}},
                           &roof));
  const ConvexSolid solid = polyhedronSolid(roof);
  const PlacedSolid placed{at(Eigen::Vector3d(0.01, 0.0, 0.0)), &solid};
  const std::vector<BoxContactFace> faces = touchingContacts(placed, placedTable(), kGap);
  ASSERT_EQ(faces.size(), 1u);
  ASSERT_EQ(faces[0].points.size(), 2u);
  for (const Eigen::Vector3d& p : faces[0].points) {
    EXPECT_NEAR(p.x(), 0.01, 1e-15);
    EXPECT_NEAR(std::abs(p.y()), 0.05, 1e-15);
    EXPECT_NEAR(p.z(), 0.0, 1e-15);
  }
  // Its least width is its height 0.03, along the top face's normal: across
  // a sloped face the far top edge lies 2 * 0.02 * 0.03 / |(0.02, 0.03)| = 0.033 away.
  EXPECT_NEAR(thinnestHalfWidth(solid), 0.015, 1e-15);
}

TEST(ConvexSolid, BoxEdgeOnATiltedFaceGivesTheEdgeEnds) {
  const double tilt = 0.3, h = 0.02;
  const Eigen::Matrix3d slope =
      Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const ConvexSolid slab = polyhedronSolid(boxPolyhedron(Eigen::Vector3d(0.2, 0.2, 0.05)));
  const PlacedSolid lower{at(Eigen::Vector3d::Zero(), slope), &slab};
  // A cube turned 45 degrees further about y stands on its edge, its centre
  // h sqrt(2) above the face along the face's normal.
  const Eigen::Vector3d n = slope.col(2);
  const ConvexSolid cube = boxSolid(Eigen::Vector3d::Constant(h));
  const PlacedSolid upper{
      at(0.05 * n + std::sqrt(2.0) * h * n,
         Eigen::AngleAxisd(tilt + M_PI / 4, Eigen::Vector3d::UnitY()).toRotationMatrix()),
      &cube};
  const std::vector<BoxContactFace> faces = touchingContacts(upper, lower, kGap);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_TRUE(faces[0].normal.isApprox(n, 1e-12));
  ASSERT_EQ(faces[0].points.size(), 2u);
  for (const Eigen::Vector3d& p : faces[0].points) {
    EXPECT_NEAR(n.dot(p), 0.05, 1e-15);
    EXPECT_NEAR(std::abs(p.y()), h, 1e-15);
    EXPECT_NEAR(slope.col(0).dot(p), 0.0, 1e-15);
  }
}

TEST(ConvexSolid, SeparationOfTurnedCubesAndPrismsByHand) {
  const ConvexSolid cube = polyhedronSolid(boxPolyhedron(Eigen::Vector3d::Constant(0.5)));
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (double d : {2.0, 1.0}) {
    // Along x the square reaches 0.5, the turned one sqrt(2)/2 (a corner);
    // along the turned one's normals d/sqrt(2) - sqrt(2)/2 - 0.5 is less.
    const PlacedSolid a{at(Eigen::Vector3d::Zero()), &cube};
    const PlacedSolid b{at(Eigen::Vector3d(d, 0, 0), turn), &cube};
    EXPECT_NEAR(separation(a, b), d - 0.5 - std::sqrt(0.5), 1e-15) << d;
    const OrientedBox box_a{a.pose, Eigen::Vector3d::Constant(0.5)};
    const OrientedBox box_b{b.pose, Eigen::Vector3d::Constant(0.5)};
    EXPECT_NEAR(separation(a, b), separation(box_a, box_b), 1e-15);
  }
  const int n = 32;
  const ConvexSolid prism = cylinder(n);
  for (double d : {0.1, 0.05}) {
    // Two prisms apart along x: the best axes are the side normals at +-pi/n
    // from x, on which each reaches its apothem r cos(pi/n).
    const PlacedSolid a{at(Eigen::Vector3d::Zero()), &prism};
    const PlacedSolid b{at(Eigen::Vector3d(d, 0, 0)), &prism};
    EXPECT_NEAR(separation(a, b), (d - 0.06) * std::cos(M_PI / n), 1e-15) << d;
  }
}

TEST(ConvexSolid, CompoundTouchesWithEachPart) {
  ConvexSolid compound;
  ConvexPart leg;  // a box part: the box routines judge it against the table
  leg.pose = at(Eigen::Vector3d(-0.1, 0, 0));
  leg.box_half_extents = Eigen::Vector3d(0.02, 0.02, 0.05);
  leg.polyhedron = boxPolyhedron(leg.box_half_extents);
  ConvexPart post;
  post.pose = at(Eigen::Vector3d(0.1, 0, 0));
  post.polyhedron = cylinderPolyhedron(0.03, 0.1, 32);
  compound.parts = {leg, post};
  const PlacedSolid placed{at(Eigen::Vector3d(0, 0, 0.05)), &compound};
  const std::vector<BoxContactFace> faces = touchingContacts(placed, placedTable(), kGap);
  ASSERT_EQ(faces.size(), 2u);
  const OrientedBox leg_box{placed.pose * leg.pose, leg.box_half_extents};
  const OrientedBox table_box{placedTable().pose, table().parts[0].box_half_extents};
  expectSameBits({faces[0]}, touchingContacts(leg_box, table_box, kGap));
  EXPECT_EQ(faces[1].points.size(), 32u);
  EXPECT_NEAR(separation(placed, placedTable()), 0.0, 1e-15);
  std::vector<Eigen::Vector3d> patch;
  Eigen::Vector3d normal;
  ASSERT_TRUE(flushContactPatch(placedTable(), placed, 1e-3, 1e-6, &patch, &normal));
  EXPECT_EQ(patch.size(), 4u + 32u);
  EXPECT_TRUE(normal.isApprox(Eigen::Vector3d::UnitZ()));

  // Lifted by 0.02 the compound is that far apart; the nearest part decides.
  const PlacedSolid lifted{at(Eigen::Vector3d(0, 0, 0.07)), &compound};
  EXPECT_NEAR(separation(lifted, placedTable()), 0.02, 1e-15);
  EXPECT_TRUE(touchingContacts(lifted, placedTable(), kGap).empty());
  EXPECT_TRUE(nearestPointIn(lifted, Eigen::Vector3d(0.5, 0, 0.07))
                  .isApprox(Eigen::Vector3d(0.13, 0, 0.07), 1e-15));
  const Eigen::Vector2d along_x = extentAlong(lifted, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(along_x.x(), -0.12, 1e-15);
  EXPECT_NEAR(along_x.y(), 0.13, 1e-15);
  EXPECT_NEAR(thinnestHalfWidth(compound), 0.02, 0.0);
}

TEST(ConvexSolid, ExtentsAndWidthsOfACylinder) {
  const ConvexSolid solid = cylinder(32);
  const PlacedSolid placed{at(Eigen::Vector3d(0.3, 0.0, 0.05)), &solid};
  const Eigen::Vector2d along_z = extentAlong(placed, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(along_z.x(), 0.0, 1e-15);
  EXPECT_NEAR(along_z.y(), 0.1, 1e-15);
  const Eigen::AlignedBox3d box = bounds(placed);
  EXPECT_NEAR(box.min().x(), 0.27, 1e-15);  // vertex 0 and 16 on the x axis
  EXPECT_NEAR(box.max().x(), 0.33, 1e-15);
  // Opposite sides are parallel: the least width is twice the apothem.
  EXPECT_NEAR(thinnestHalfWidth(solid), 0.03 * std::cos(M_PI / 32), 1e-15);
  EXPECT_NEAR(radiusAbout(solid, Eigen::Vector3d::Zero()), std::hypot(0.03, 0.05), 1e-15);
  EXPECT_NEAR(thinnestHalfWidth(boxSolid(Eigen::Vector3d(0.1, 0.02, 0.05))), 0.02, 0.0);
}

TEST(ConvexSolid, NearestPointOfATetrahedron) {
  ConvexPolyhedron tetra;
  ASSERT_TRUE(convexHull3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, &tetra));
  const ConvexSolid solid = polyhedronSolid(tetra);
  const PlacedSolid placed{at(Eigen::Vector3d(1, 2, 3)), &solid};
  const Eigen::Vector3d origin(1, 2, 3);
  auto nearest = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return nearestPointIn(placed, origin + p) - origin;
  };
  // Inside: itself. Above the slanted face's middle: its centre. Beyond a
  // corner: the corner. Below the base: straight up onto it.
  EXPECT_TRUE(
      nearest(Eigen::Vector3d(0.2, 0.2, 0.2)).isApprox(Eigen::Vector3d(0.2, 0.2, 0.2), 1e-15));
  EXPECT_TRUE(
      nearest(Eigen::Vector3d(1, 1, 1)).isApprox(Eigen::Vector3d::Constant(1.0 / 3.0), 1e-15));
  EXPECT_LT(nearest(Eigen::Vector3d(-1, -1, -1)).norm(), 1e-15);
  EXPECT_TRUE(nearest(Eigen::Vector3d(3, -1, -1)).isApprox(Eigen::Vector3d(1, 0, 0), 1e-15));
  EXPECT_TRUE(
      nearest(Eigen::Vector3d(0.25, 0.25, -1)).isApprox(Eigen::Vector3d(0.25, 0.25, 0), 1e-15));
  // Beyond the edge x + y = 1 at z = 0: its middle.
  EXPECT_TRUE(nearest(Eigen::Vector3d(1, 1, -1)).isApprox(Eigen::Vector3d(0.5, 0.5, 0), 1e-15));
}

}  // namespace
}  // namespace brick_stack_sim
