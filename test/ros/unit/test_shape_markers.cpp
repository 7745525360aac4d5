// ~markers of bricks that are not boxes: a cylinder as one CYLINDER, a hull
// as a TRIANGLE_LIST of its faces, a compound as one marker per part with
// ids that no other brick's share, their outlines, and a box brick with a
// solid drawn exactly as one without; checked against values worked out by
// hand here.
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/ros/markers.h"
#include "support/shapes.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRadius = 0.02;  // [m]
constexpr double kLength = 0.05;  // [m]
// The wedge: a ramp over x in [-a, a], y in [-b, b], rising to h over y = -b.
constexpr double kWedgeA = 0.03;   // [m]
constexpr double kWedgeB = 0.02;   // [m]
constexpr double kWedgeH = 0.015;  // [m]

BrickType finished(BrickType type) { return test::finishedType(std::move(type)); }

BrickType cylinderType() { return test::cylinderType("peg", kRadius, kLength, 0.1); }

BrickType wedgeType() { return test::rampType("wedge", kWedgeA, kWedgeB, kWedgeH, 0.05); }

/// A box 0.04 x 0.02 x 0.01 m at x = -0.02 and a cylinder (r 0.01 m,
/// length 0.02 m) lying along y at x = +0.03, in the type frame.
BrickType compoundType() {
  BrickType t;
  t.name = "hammer";
  t.shape.kind = ShapeKind::kCompound;
  ShapePart box;
  box.size = Eigen::Vector3d(0.04, 0.02, 0.01);
  box.pose.translation() = Eigen::Vector3d(-0.02, 0.0, 0.0);
  ShapePart peg;
  peg.kind = ShapeKind::kCylinder;
  peg.radius = 0.01;
  peg.length = 0.02;
  peg.pose.translation() = Eigen::Vector3d(0.03, 0.0, 0.0);
  peg.pose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  t.shape.parts = {box, peg};
  t.mass = 0.08;
  return finished(t);
}

BrickSnapshot brickOf(const BrickType& type, unsigned serial, const Eigen::Isometry3d& pose) {
  BrickSnapshot brick;
  brick.id = type.name + std::to_string(serial);
  brick.type = type.name;
  brick.serial = serial;
  brick.pose = pose;
  brick.size = type.size;
  brick.solid = type.solid;
  brick.mass = type.mass;
  brick.state = BrickState::kStable;
  return brick;
}

Eigen::Isometry3d turnedPose(const Eigen::Vector3d& at) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = at;
  pose.linear() =
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(0.3, -0.2, 1.0).normalized()).toRotationMatrix();
  return pose;
}

Eigen::Vector3d toEigen(const geometry_msgs::Point& p) { return Eigen::Vector3d(p.x, p.y, p.z); }

Eigen::Isometry3d fromPoseMsg(const geometry_msgs::Pose& msg) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(msg.position.x, msg.position.y, msg.position.z);
  pose.linear() =
      Eigen::Quaterniond(msg.orientation.w, msg.orientation.x, msg.orientation.y, msg.orientation.z)
          .toRotationMatrix();
  return pose;
}

/// The ADD markers of a namespace.
std::vector<const Marker*> added(const MarkerArray& array, const std::string& ns) {
  std::vector<const Marker*> found;
  for (const Marker& m : array.markers)
    if (m.ns == ns && m.action == Marker::ADD) found.push_back(&m);
  return found;
}

const Marker& edgesOf(const MarkerArray& array) {
  const std::vector<const Marker*> edges = added(array, kBrickEdgeMarkerNamespace);
  EXPECT_EQ(edges.size(), 1u);
  return *edges.front();
}

void expectAllFinite(const MarkerArray& array) {
  for (const Marker& m : array.markers) {
    EXPECT_TRUE(std::isfinite(m.pose.position.x) && std::isfinite(m.pose.position.y) &&
                std::isfinite(m.pose.position.z) && std::isfinite(m.pose.orientation.w) &&
                std::isfinite(m.pose.orientation.x) && std::isfinite(m.scale.x) &&
                std::isfinite(m.scale.y) && std::isfinite(m.scale.z))
        << m.ns << " " << m.id;
    for (const geometry_msgs::Point& p : m.points)
      EXPECT_TRUE(toEigen(p).allFinite()) << m.ns << " " << m.id;
  }
}

TEST(ShapeMarkers, ACylinderIsOneCylinderOfItsRadiusAndLength) {
  const BrickType peg = cylinderType();
  const BrickSnapshot brick = brickOf(peg, 7, turnedPose({0.1, -0.05, 0.03}));
  const MarkerArray array = makeBrickMarkers({brick}, "world", ros::Time(1.0));
  expectAllFinite(array);
  const std::vector<const Marker*> bodies = added(array, kBrickMarkerNamespace);
  ASSERT_EQ(bodies.size(), 1u);
  const Marker& body = *bodies.front();
  EXPECT_EQ(body.type, Marker::CYLINDER);
  EXPECT_EQ(body.id, 7);
  EXPECT_EQ(body.scale.x, 0.04);
  EXPECT_EQ(body.scale.y, 0.04);
  EXPECT_EQ(body.scale.z, 0.05);
  EXPECT_TRUE(fromPoseMsg(body.pose).isApprox(brick.pose, 1e-12));
  EXPECT_EQ(body.color.a, 1.0f);
  EXPECT_EQ(body.color.r, brickColor(brick).r);
  // The outline: the two cap rims and nothing else, each point on the rim
  // circle kBrickEdgeInflation outside the cylinder.
  const Marker& edges = edgesOf(array);
  ASSERT_EQ(edges.points.size(), 2u * 2u * kCylinderRimSegments);
  const double rim_radius = kRadius + kBrickEdgeInflation;
  const double rim_z = 0.5 * kLength + kBrickEdgeInflation;
  int upper = 0;
  for (const geometry_msgs::Point& p : edges.points) {
    const Eigen::Vector3d local = brick.pose.inverse() * toEigen(p);
    EXPECT_NEAR(local.head<2>().norm(), rim_radius, 1e-12);
    EXPECT_NEAR(std::abs(local.z()), rim_z, 1e-12);
    upper += local.z() > 0.0;
  }
  EXPECT_EQ(upper, 2 * kCylinderRimSegments);
}

TEST(ShapeMarkers, AHullIsATriangleListOfItsFacesFacingOut) {
  const BrickType wedge = wedgeType();
  const BrickSnapshot brick = brickOf(wedge, 3, turnedPose({-0.1, 0.2, 0.01}));
  const MarkerArray array = makeBrickMarkers({brick}, "world", ros::Time(1.0));
  expectAllFinite(array);
  const std::vector<const Marker*> bodies = added(array, kBrickMarkerNamespace);
  ASSERT_EQ(bodies.size(), 1u);
  const Marker& body = *bodies.front();
  EXPECT_EQ(body.type, Marker::TRIANGLE_LIST);
  EXPECT_EQ(body.scale.x, 1.0);
  EXPECT_EQ(body.scale.y, 1.0);
  EXPECT_EQ(body.scale.z, 1.0);
  const ConvexPolyhedron& hull = wedge.solid->parts.at(0).polyhedron;
  std::size_t triangles = 0;
  for (const ConvexPolyhedron::Face& face : hull.faces) triangles += face.loop.size() - 2;
  // By hand: a bottom, a back and a slope of 2 triangles each, two ends of 1.
  EXPECT_EQ(triangles, 8u);
  ASSERT_EQ(body.points.size(), 3u * triangles);
  // The points are in the part's frame (the type frame here), the pose the brick's.
  EXPECT_TRUE(fromPoseMsg(body.pose).isApprox(brick.pose, 1e-12));
  for (std::size_t i = 0; i < body.points.size(); i += 3) {
    const Eigen::Vector3d a = toEigen(body.points[i]), b = toEigen(body.points[i + 1]),
                          c = toEigen(body.points[i + 2]);
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    // All three on one plane of the wedge, the triangle facing out of it.
    bool on_a_face = false;
    for (const ConvexPolyhedron::Face& face : hull.faces) {
      const bool on = std::abs(face.normal.dot(a) - face.offset) < 1e-12 &&
                      std::abs(face.normal.dot(b) - face.offset) < 1e-12 &&
                      std::abs(face.normal.dot(c) - face.offset) < 1e-12;
      if (on) {
        EXPECT_GT(normal.dot(face.normal), 1.0 - 1e-9) << "triangle " << i / 3;
      }
      on_a_face = on_a_face || on;
    }
    EXPECT_TRUE(on_a_face) << "triangle " << i / 3;
    for (const Eigen::Vector3d& p : {a, b, c}) {  // inside the wedge as defined by hand
      EXPECT_LE(std::abs(p.x()), kWedgeA + 1e-12);
      EXPECT_LE(std::abs(p.y()), kWedgeB + 1e-12);
      EXPECT_GE(p.z(), -1e-12);
      EXPECT_LE(p.z(), kWedgeH * (kWedgeB - p.y()) / (2.0 * kWedgeB) + 1e-12);
    }
  }
  // The outline: the wedge's nine edges.
  EXPECT_EQ(hull.edges.size(), 9u);
  EXPECT_EQ(edgesOf(array).points.size(), 2u * 9u);
}

TEST(ShapeMarkers, ACompoundIsOneTriangleListOfAllItsPartsWithTheBricksId) {
  const BrickType hammer = compoundType();
  const BrickType peg = cylinderType();
  const std::vector<BrickSnapshot> bricks = {brickOf(hammer, 4, turnedPose({0.0, 0.0, 0.02})),
                                             brickOf(hammer, 5, turnedPose({0.1, 0.0, 0.02})),
                                             brickOf(peg, 6, turnedPose({0.2, 0.0, 0.03}))};
  const MarkerArray array = makeBrickMarkers(bricks, "world", ros::Time(1.0));
  expectAllFinite(array);
  // One body per brick, whatever its parts, all in `bricks`.
  EXPECT_EQ(added(array, kBrickMarkerNamespace).size(), 3u);
  std::set<std::pair<std::string, int>> keys;
  for (const Marker& m : array.markers) {
    if (m.action != Marker::ADD) continue;
    EXPECT_TRUE(keys.emplace(m.ns, m.id).second) << "two markers " << m.ns << " " << m.id;
  }
  const BrickSnapshot& first = bricks[0];
  for (const Marker* m : added(array, kBrickMarkerNamespace)) {
    if (m->id != 4) continue;
    EXPECT_EQ(m->type, Marker::TRIANGLE_LIST);
    EXPECT_TRUE(fromPoseMsg(m->pose).isApprox(first.pose, 1e-12));
    // The box part's 6 faces of 2 triangles and the cylinder's prism: its
    // sides of 2 triangles each and two caps of (sides - 2).
    const ConvexPolyhedron& prism = hammer.solid->parts.at(1).polyhedron;
    const std::size_t sides = prism.faces.size() - 2;
    EXPECT_EQ(m->points.size(), 3u * (12u + 2u * sides + 2u * (sides - 2u)));
    // The box part spans x in [-0.04, 0] of the brick's frame, the cylinder
    // part [0.02, 0.04]: every point lies in one of them.
    for (const geometry_msgs::Point& p : m->points) {
      const Eigen::Vector3d local = toEigen(p);
      const bool in_box = local.x() >= -0.04 - 1e-12 && local.x() <= 1e-12;
      const bool in_cylinder = local.x() >= 0.02 - 1e-12 && local.x() <= 0.04 + 1e-12;
      EXPECT_TRUE(in_box || in_cylinder) << local.transpose();
    }
  }
  // Outlines: per hammer a box's 12 edges and two rims, then the peg's rims.
  const std::size_t rims = 2u * 2u * kCylinderRimSegments;
  EXPECT_EQ(edgesOf(array).points.size(), 2u * (24u + rims) + rims);
}

TEST(ShapeMarkers, ABoxBrickWithASolidIsDrawnAsOneWithout) {
  BrickType kapla;
  kapla.name = "kapla";
  kapla.size = Eigen::Vector3d(0.117, 0.0234, 0.0078);
  kapla.mass = 0.0119;
  kapla = finished(kapla);
  ASSERT_TRUE(kapla.solid);
  BrickSnapshot with = brickOf(kapla, 9, turnedPose({0.05, 0.04, 0.0039}));
  BrickSnapshot without = with;
  without.solid.reset();
  const MarkerArray a = makeBrickMarkers({with}, "world", ros::Time(2.0));
  const MarkerArray b = makeBrickMarkers({without}, "world", ros::Time(2.0));
  EXPECT_TRUE(a == b);
  ASSERT_EQ(added(a, kBrickMarkerNamespace).size(), 1u);
  EXPECT_EQ(added(a, kBrickMarkerNamespace).front()->type, Marker::CUBE);
  EXPECT_EQ(edgesOf(a).points.size(), 24u);
}

TEST(ShapeMarkers, NothingNonFiniteReachesAMarker) {
  const BrickType peg = cylinderType(), wedge = wedgeType(), hammer = compoundType();
  std::vector<BrickSnapshot> bricks;
  unsigned serial = 0;
  for (const BrickType* type : {&peg, &wedge, &hammer}) {
    Eigen::Isometry3d broken = turnedPose({0.0, 0.0, 0.1});
    broken.translation().y() = kNaN;
    bricks.push_back(brickOf(*type, serial++, broken));
    broken = turnedPose({0.0, 0.0, 0.1});
    broken.linear()(1, 2) = std::numeric_limits<double>::infinity();
    bricks.push_back(brickOf(*type, serial++, broken));
  }
  const MarkerArray array = makeBrickMarkers(bricks, "world", ros::Time(1.0));
  // Only the DELETEALL: no body and no outline.
  ASSERT_EQ(array.markers.size(), 1u);
  EXPECT_EQ(array.markers.front().action, Marker::DELETEALL);
  // A finite brick among them is drawn, and only it.
  bricks.push_back(brickOf(wedge, serial, turnedPose({0.0, 0.0, 0.1})));
  const MarkerArray some = makeBrickMarkers(bricks, "world", ros::Time(1.0));
  expectAllFinite(some);
  EXPECT_EQ(added(some, kBrickMarkerNamespace).size(), 1u);
  EXPECT_EQ(edgesOf(some).points.size(), 2u * 9u);
}

TEST(ShapeMarkers, AGhostIsDrawnByTheSameCodeRelativeToItsFrame) {
  const BrickType peg = cylinderType(), hammer = compoundType();
  const std_msgs::ColorRGBA blue = rgb(0.2f, 0.6f, 1.0f, 0.75f);
  const Eigen::Isometry3d here = Eigen::Isometry3d::Identity();
  std::vector<Marker> markers = solidBodyMarkers(peg.solid.get(), peg.size, here, blue);
  ASSERT_EQ(markers.size(), 1u);
  EXPECT_EQ(markers[0].type, Marker::CYLINDER);
  EXPECT_EQ(markers[0].color.a, 0.75f);
  EXPECT_EQ(markers[0].pose.orientation.w, 1.0);
  EXPECT_EQ(solidBodyMarkers(hammer.solid.get(), hammer.size, here, blue).size(), 2u);
  // No solid: the box of the size; a size that is not finite: nothing.
  markers = solidBodyMarkers(nullptr, Eigen::Vector3d(0.1, 0.02, 0.01), here, blue);
  ASSERT_EQ(markers.size(), 1u);
  EXPECT_EQ(markers[0].type, Marker::CUBE);
  EXPECT_EQ(markers[0].scale.x, 0.1);
  EXPECT_TRUE(solidBodyMarkers(nullptr, Eigen::Vector3d(kNaN, 0.02, 0.01), here, blue).empty());
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
