#include <chrono>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/convex_polyhedron.h"

namespace brick_stack_sim {
namespace {

/// Checks what every polyhedron promises: unit outward normals, loops on
/// their planes and counter-clockwise seen from outside, convexity, every
/// edge listed once and walked once each way, Euler's V - E + F = 2.
void expectWellFormed(const ConvexPolyhedron& p, double tolerance) {
  std::map<std::pair<int, int>, int> walked;
  for (const ConvexPolyhedron::Face& face : p.faces) {
    ASSERT_GE(face.loop.size(), 3u);
    EXPECT_NEAR(face.normal.norm(), 1.0, 1e-12);
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < face.loop.size(); ++i) {
      const Eigen::Vector3d& a = p.vertices[face.loop[i]];
      const Eigen::Vector3d& b = p.vertices[face.loop[(i + 1) % face.loop.size()]];
      EXPECT_NEAR(face.normal.dot(a), face.offset, tolerance);
      newell += a.cross(b);
      ++walked[{face.loop[i], face.loop[(i + 1) % face.loop.size()]}];
    }
    EXPECT_GT(newell.dot(face.normal), 0.0);  // twice the area, along the normal
    for (const Eigen::Vector3d& v : p.vertices)
      EXPECT_LE(face.normal.dot(v), face.offset + tolerance);
  }
  for (const auto& [edge, count] : walked) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(walked.count({edge.second, edge.first}), 1u);
  }
  std::set<std::pair<int, int>> listed;
  for (const auto& e : p.edges) EXPECT_TRUE(listed.insert({e[0], e[1]}).second);
  EXPECT_EQ(listed.size(), walked.size() / 2);
  for (const auto& e : p.edges) EXPECT_EQ(walked.count({e[0], e[1]}), 1u);
  EXPECT_EQ(static_cast<int>(p.vertices.size()) - static_cast<int>(p.edges.size()) +
                static_cast<int>(p.faces.size()),
            2);
}

TEST(ConvexPolyhedron, BoxHasSixSquareFacesOnItsHalfExtents) {
  const Eigen::Vector3d half(0.5, 0.25, 0.125);
  const ConvexPolyhedron box = boxPolyhedron(half);
  EXPECT_EQ(box.vertices.size(), 8u);
  EXPECT_EQ(box.edges.size(), 12u);
  ASSERT_EQ(box.faces.size(), 6u);
  for (const ConvexPolyhedron::Face& face : box.faces) {
    EXPECT_EQ(face.loop.size(), 4u);
    int axis;
    EXPECT_NEAR(face.normal.cwiseAbs().maxCoeff(&axis), 1.0, 0.0);
    EXPECT_EQ(face.offset, half[axis]);
  }
  expectWellFormed(box, 1e-15);
}

TEST(ConvexPolyhedron, CylinderPrismHasItsVerticesOnTheCircle) {
  const double r = 0.03, length = 0.1;
  const int n = 16;
  const ConvexPolyhedron prism = cylinderPolyhedron(r, length, n);
  EXPECT_EQ(prism.vertices.size(), 2u * n);
  EXPECT_EQ(prism.faces.size(), n + 2u);
  EXPECT_EQ(prism.edges.size(), 3u * n);
  EXPECT_TRUE(prism.vertices[0].isApprox(Eigen::Vector3d(r, 0.0, -0.5 * length)));
  for (const Eigen::Vector3d& v : prism.vertices) {
    EXPECT_NEAR(v.head<2>().norm(), r, 1e-15);
    EXPECT_NEAR(std::abs(v.z()), 0.5 * length, 0.0);
  }
  // The side faces sag inside the circle by r (1 - cos(pi / n)) at their middles.
  for (std::size_t i = 2; i < prism.faces.size(); ++i)
    EXPECT_NEAR(r - prism.faces[i].offset, r * (1.0 - std::cos(M_PI / n)), 1e-15);
  EXPECT_EQ(prism.faces[0].loop.size(), static_cast<std::size_t>(n));
  expectWellFormed(prism, 1e-15);
}

TEST(ConvexPolyhedron, CylinderSidesAreTheFewestWithinTheSag) {
  // r (1 - cos(pi / n)) <= 1e-4 at r = 0.05: cos(pi / n) >= 0.998, n >= 49.7, so 50.
  EXPECT_EQ(cylinderSides(0.05, 1e-4), 50);
  EXPECT_GT(0.05 * (1.0 - std::cos(M_PI / 48)), 1e-4);
  EXPECT_EQ(cylinderSides(0.05, 1.0), 16);
  EXPECT_EQ(cylinderSides(0.05, 1e-12), 256);
}

TEST(ConvexHull, CubeWithFaceAndEdgePointsKeepsItsEightCorners) {
  std::vector<Eigen::Vector3d> points;
  // Face centres and edge midpoints first: the hull must not keep them as corners.
  for (int k = 0; k < 3; ++k) {
    for (double s : {-1.0, 1.0}) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      centre[k] = s;
      points.push_back(centre);
      for (double t : {-1.0, 1.0}) {
        Eigen::Vector3d middle = centre;
        middle[(k + 1) % 3] = t;
        points.push_back(middle);
      }
    }
  }
  points.push_back(Eigen::Vector3d(0.3, -0.2, 0.5));
  for (int i = 0; i < 8; ++i)
    points.emplace_back((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
  points.push_back(Eigen::Vector3d(1.0, 1.0, 1.0));  // repeated, as in a mesh
  ConvexPolyhedron hull;
  ASSERT_TRUE(convexHull3d(points, &hull));
  EXPECT_EQ(hull.vertices.size(), 8u);
  EXPECT_EQ(hull.edges.size(), 12u);
  ASSERT_EQ(hull.faces.size(), 6u);
  for (const ConvexPolyhedron::Face& face : hull.faces) {
    EXPECT_EQ(face.loop.size(), 4u);
    EXPECT_NEAR(face.normal.cwiseAbs().maxCoeff(), 1.0, 1e-15);
    EXPECT_NEAR(face.offset, 1.0, 1e-15);
  }
  for (const Eigen::Vector3d& v : hull.vertices) EXPECT_NEAR(v.cwiseAbs().minCoeff(), 1.0, 0.0);
  expectWellFormed(hull, 1e-12);
}

TEST(ConvexHull, RotatedLatticeMergesIntoSixFaces) {
  // A 6x6x6 lattice turned off the axes: its faces hold 36 rounded, coplanar points each.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k)
        points.push_back(turn * Eigen::Vector3d(0.1 * i, 0.1 * j, 0.1 * k));
  ConvexPolyhedron hull;
  ASSERT_TRUE(convexHull3d(points, &hull));
  EXPECT_EQ(hull.vertices.size(), 8u);
  ASSERT_EQ(hull.faces.size(), 6u);
  for (const ConvexPolyhedron::Face& face : hull.faces) EXPECT_EQ(face.loop.size(), 4u);
  EXPECT_NEAR(solidMass(hull).volume, 0.125, 1e-14);
  expectWellFormed(hull, 1e-12);
}

std::vector<Eigen::Vector3d> pointsOnSphere(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i)
    points.push_back(Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized());
  return points;
}

TEST(ConvexHull, RandomPointsOnASphereAreAllOnOrInside) {
  std::vector<Eigen::Vector3d> points = pointsOnSphere(2000, 7);
  for (int i = 0; i < 200; ++i) points.push_back(0.9 * points[i]);  // inside
  ConvexPolyhedron hull;
  ASSERT_TRUE(convexHull3d(points, &hull));
  // Points in general position: every one on the sphere is a corner, none inside.
  EXPECT_EQ(hull.vertices.size(), 2000u);
  for (const Eigen::Vector3d& v : hull.vertices) EXPECT_NEAR(v.norm(), 1.0, 1e-12);
  for (const ConvexPolyhedron::Face& face : hull.faces) {
    EXPECT_EQ(face.loop.size(), 3u);
    for (const Eigen::Vector3d& p : points) EXPECT_LE(face.normal.dot(p), face.offset + 1e-12);
  }
  expectWellFormed(hull, 1e-12);
}

TEST(ConvexHull, TwentyThousandMeshPointsTakeWellUnderASecond) {
  // A mesh lists each corner several times; many on its hull.
  std::vector<Eigen::Vector3d> points = pointsOnSphere(10000, 11);
  for (int i = 0; i < 10000; ++i) points.push_back(points[(i * 7919) % 10000]);
  const auto start = std::chrono::steady_clock::now();
  ConvexPolyhedron hull;
  ASSERT_TRUE(convexHull3d(points, &hull));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0);  // generous: a shared, unoptimised test machine
  EXPECT_EQ(hull.vertices.size(), 10000u);
  EXPECT_EQ(static_cast<int>(hull.vertices.size()) - static_cast<int>(hull.edges.size()) +
                static_cast<int>(hull.faces.size()),
            2);
}

TEST(ConvexHull, NearlyCoplanarAndCollinearPointsKeepTheSurfaceClosed) {
  // Points on a turned cube's faces, lifted off them by about the tolerance
  // (1e-9 of the 0.17 m diagonal), and points along a prism's side edges:
  // the cases where rounding folds a naive hull.
  std::mt19937 random(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.8, Eigen::Vector3d(3, -1, 2).normalized()).toRotationMatrix();
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 1000; ++i) {
      Eigen::Vector3d p(u(random), u(random), u(random));
      p[i % 3] = (i % 2) ? 1.0 : -1.0;
      points.push_back(0.05 * (turn * (p + 4e-9 * Eigen::Vector3d(u(random), u(random), 0.0))));
    }
    for (int i = 0; i < 24; ++i)
      for (int k = 0; k <= 5; ++k)
        points.emplace_back(std::cos(i * M_PI / 12), std::sin(i * M_PI / 12), 0.2 * k + 2.0);
    ConvexPolyhedron hull;
    ASSERT_TRUE(convexHull3d(points, &hull));
    for (const ConvexPolyhedron::Face& face : hull.faces)
      for (const Eigen::Vector3d& p : points) ASSERT_LE(face.normal.dot(p) - face.offset, 1e-9);
    expectWellFormed(hull, 1e-9);
  }
}

TEST(ConvexHull, PrismCapsAreSingleFaces) {
  const ConvexPolyhedron prism = cylinderPolyhedron(0.03, 0.1, 24);
  ConvexPolyhedron hull;
  ASSERT_TRUE(convexHull3d(prism.vertices, &hull));
  EXPECT_EQ(hull.vertices.size(), 48u);
  ASSERT_EQ(hull.faces.size(), 26u);
  int caps = 0;
  for (const ConvexPolyhedron::Face& face : hull.faces) {
    if (std::abs(face.normal.z()) > 0.5) {
      ++caps;
      EXPECT_EQ(face.loop.size(), 24u);
      EXPECT_NEAR(face.offset, 0.05, 1e-15);
    } else {
      EXPECT_EQ(face.loop.size(), 4u);
    }
  }
  EXPECT_EQ(caps, 2);
  expectWellFormed(hull, 1e-13);
}

TEST(ConvexHull, PointsSpanningNoVolumeAreRefusedWithAReason) {
  ConvexPolyhedron hull;
  Status status = convexHull3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, &hull);
  EXPECT_FALSE(status);
  EXPECT_NE(status.message.find("fewer than 4 points"), std::string::npos) << status.message;

  std::vector<Eigen::Vector3d> flat;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) flat.emplace_back(i, j, 0.5 * i - 0.25 * j);  // one plane
  status = convexHull3d(flat, &hull);
  EXPECT_FALSE(status);
  EXPECT_NE(status.message.find("points are coplanar: they span no volume"), std::string::npos)
      << status.message;

  status = convexHull3d({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {3, 3, 3}}, &hull);
  EXPECT_FALSE(status);
  EXPECT_NE(status.message.find("coplanar"), std::string::npos) << status.message;

  status = convexHull3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}}, &hull);
  EXPECT_FALSE(status);
  EXPECT_NE(status.message.find("a point is not finite"), std::string::npos) << status.message;
}

TEST(SolidMass, BoxMatchesItsClosedForm) {
  const Eigen::Vector3d size(1.0, 0.5, 0.25);
  const SolidMass mass = solidMass(boxPolyhedron(0.5 * size));
  const double v = size.prod();
  EXPECT_NEAR(mass.volume, v, 1e-15);
  EXPECT_NEAR(mass.centroid.norm(), 0.0, 1e-15);
  // m/12 (b^2 + c^2) and so on, off the diagonal zero.
  const Eigen::Vector3d s = size.cwiseProduct(size);
  const Eigen::Matrix3d expected =
      (v / 12.0 * Eigen::Vector3d(s.y() + s.z(), s.x() + s.z(), s.x() + s.y())).asDiagonal();
  EXPECT_TRUE(mass.inertia.isApprox(expected, 1e-13)) << mass.inertia;
}

TEST(SolidMass, PrismConvergesOnTheCylinder) {
  const double r = 0.1, length = 0.3;
  for (int n : {16, 64, 256}) {
    const SolidMass mass = solidMass(cylinderPolyhedron(r, length, n));
    // n triangles of two sides r at 2 pi / n: area n/2 r^2 sin, polar moment
    // r^4 sin (2 + cos) / 12 each.
    const double angle = 2.0 * M_PI / n;
    const double area = 0.5 * n * r * r * std::sin(angle);
    EXPECT_NEAR(mass.volume, area * length, 1e-15);
    const double polar = n * std::pow(r, 4) * std::sin(angle) * (2.0 + std::cos(angle)) / 12.0;
    EXPECT_NEAR(mass.inertia(2, 2), polar * length, 1e-16);
    EXPECT_NEAR(mass.centroid.norm(), 0.0, 1e-15);
  }
  const SolidMass fine = solidMass(cylinderPolyhedron(r, length, 256));
  EXPECT_NEAR(fine.volume / (M_PI * r * r * length), 1.0, 1e-3);
  EXPECT_NEAR(fine.inertia(2, 2) / fine.volume / (0.5 * r * r), 1.0, 1e-3);
  const double across = (3.0 * r * r + length * length) / 12.0;
  EXPECT_NEAR(fine.inertia(0, 0) / fine.volume / across, 1.0, 1e-3);
}

TEST(SolidMass, CornerTetrahedron) {
  ConvexPolyhedron tetra;
  ASSERT_TRUE(convexHull3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, &tetra));
  const SolidMass mass = solidMass(tetra);
  EXPECT_NEAR(mass.volume, 1.0 / 6.0, 1e-15);
  EXPECT_TRUE(mass.centroid.isApprox(Eigen::Vector3d::Constant(0.25), 1e-14));
  // About the origin: int x^2 = 1/60, int x y = 1/120; about the centroid
  // less V/16 each: 1/160 and -1/480. So I_xx = 2/160, I_xy = +1/480.
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(mass.inertia(i, j), i == j ? 1.0 / 80.0 : 1.0 / 480.0, 1e-15) << i << j;
  }
}

TEST(SolidMass, RightTriangularPrism) {
  const double a = 0.3, b = 0.2, length = 0.5;
  ConvexPolyhedron prism;
  ASSERT_TRUE(convexHull3d(
      {{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, length}, {a, 0, length}, {0, b, length}}, &prism));
  EXPECT_EQ(prism.faces.size(), 5u);
  const SolidMass mass = solidMass(prism);
  const double v = 0.5 * a * b * length;
  EXPECT_NEAR(mass.volume, v, 1e-15);
  EXPECT_TRUE(mass.centroid.isApprox(Eigen::Vector3d(a / 3, b / 3, length / 2), 1e-14));
  // Right triangle about its centroid: int y'^2 = a b^3/36, int x'^2 = b a^3/36,
  // int x'y' = -a^2 b^2/72; times the length, plus the extrusion's area L^3/12.
  EXPECT_NEAR(mass.inertia(0, 0),
              length * a * b * b * b / 36 + 0.5 * a * b * std::pow(length, 3) / 12, 1e-15);
  EXPECT_NEAR(mass.inertia(1, 1),
              length * b * a * a * a / 36 + 0.5 * a * b * std::pow(length, 3) / 12, 1e-15);
  EXPECT_NEAR(mass.inertia(2, 2), length * a * b * (a * a + b * b) / 36, 1e-15);
  EXPECT_NEAR(mass.inertia(0, 1), length * a * a * b * b / 72, 1e-15);
  EXPECT_NEAR(mass.inertia(0, 2), 0.0, 1e-15);
  EXPECT_NEAR(mass.inertia(1, 2), 0.0, 1e-15);
}

ConvexPolyhedron moved(ConvexPolyhedron p, const Eigen::Isometry3d& pose) {
  for (Eigen::Vector3d& v : p.vertices) v = pose * v;
  for (ConvexPolyhedron::Face& f : p.faces) {
    f.normal = pose.linear() * f.normal;
    f.offset += f.normal.dot(pose.translation());
  }
  return p;
}

TEST(SolidMass, OffCentreBoxKeepsItsInertiaAboutTheCentroid) {
  const Eigen::Vector3d half(0.4, 0.1, 0.05), shift(1.0, -2.0, 0.5);
  const SolidMass centred = solidMass(boxPolyhedron(half));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = shift;
  const SolidMass off = solidMass(moved(boxPolyhedron(half), pose));
  EXPECT_NEAR(off.volume, centred.volume, 1e-14);
  EXPECT_TRUE(off.centroid.isApprox(shift, 1e-14));
  EXPECT_TRUE(off.inertia.isApprox(centred.inertia, 1e-12));
  // Parallel axes: about the origin, I + V (|d|^2 1 - d d^T); its x row by hand.
  const Eigen::Matrix3d about_origin =
      off.inertia +
      off.volume * (shift.squaredNorm() * Eigen::Matrix3d::Identity() - shift * shift.transpose());
  EXPECT_NEAR(about_origin(0, 0), centred.inertia(0, 0) + off.volume * (4.0 + 0.25), 1e-14);
  EXPECT_NEAR(about_origin(0, 1), off.volume * 2.0, 1e-14);  // -V dx dy = -V (1)(-2)
}

TEST(SolidMass, RotatedBoxHasProductsOfInertia) {
  const Eigen::Vector3d half(0.4, 0.1, 0.05);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(-0.4, Eigen::Vector3d(1, 1, 0).normalized()))
                      .toRotationMatrix();
  const SolidMass rotated = solidMass(moved(boxPolyhedron(half), pose));
  const Eigen::Matrix3d r = pose.linear();
  const Eigen::Matrix3d expected = r * solidMass(boxPolyhedron(half)).inertia * r.transpose();
  EXPECT_GT(std::abs(expected(0, 1)), 1e-4);
  EXPECT_TRUE(rotated.inertia.isApprox(expected, 1e-12)) << rotated.inertia;
}

}  // namespace
}  // namespace brick_stack_sim
