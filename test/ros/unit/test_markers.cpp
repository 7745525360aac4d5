// ~markers as a pure function of snapshots, support geometry and the table:
// opaque boxes with outlines, COM-above rays, contact meshes, contact forces,
// the table and the legend, checked against geometry computed here (areas,
// heights, cone angles, corners) and against a real world in mode com.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/polygon2d.h"
#include "brick_stack_sim/ros/markers.h"
#include "support/kapla.h"
#include "support/leaning.h"
#include "support/world_probe.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const Marker* findMarker(const MarkerArray& array, const std::string& ns, int id) {
  for (const Marker& marker : array.markers)
    if (marker.ns == ns && marker.id == id && marker.action == Marker::ADD) return &marker;
  return nullptr;
}

int countInNamespace(const MarkerArray& array, const std::string& ns) {
  int count = 0;
  for (const Marker& marker : array.markers) count += marker.ns == ns;
  return count;
}

bool isGreen(const std_msgs::ColorRGBA& c) { return c.g > 0.8f && c.r < 0.5f && c.b < 0.5f; }
bool isRed(const std_msgs::ColorRGBA& c) { return c.r > 0.8f && c.g < 0.5f && c.b < 0.5f; }

Eigen::Vector3d toEigen(const geometry_msgs::Point& p) { return Eigen::Vector3d(p.x, p.y, p.z); }

/// Sum of the areas of a TRIANGLE_LIST's triangles projected on the xy plane,
/// signed: counter-clockwise seen from above counts positive [m^2].
double signedTriangleArea(const Marker& marker) {
  double total = 0.0;
  for (std::size_t i = 0; i + 2 < marker.points.size(); i += 3) {
    const Eigen::Vector3d a = toEigen(marker.points[i]);
    const Eigen::Vector3d b = toEigen(marker.points[i + 1]);
    const Eigen::Vector3d c = toEigen(marker.points[i + 2]);
    total += 0.5 * ((b - a).cross(c - a)).z();
  }
  return total;
}

/// Shoelace area of a polygon's projection [m^2], computed here independently
/// of the code under test.
double shoelace(const std::vector<Eigen::Vector3d>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % polygon.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

/// Every number of every marker is finite.
void expectAllFinite(const MarkerArray& array) {
  for (const Marker& m : array.markers) {
    EXPECT_TRUE(std::isfinite(m.pose.position.x) && std::isfinite(m.pose.position.y) &&
                std::isfinite(m.pose.position.z) && std::isfinite(m.pose.orientation.w) &&
                std::isfinite(m.scale.x) && std::isfinite(m.scale.y) && std::isfinite(m.scale.z))
        << m.ns << " " << m.id;
    for (const geometry_msgs::Point& p : m.points)
      EXPECT_TRUE(toEigen(p).allFinite()) << m.ns << " " << m.id;
  }
}

BrickSnapshot brickAt(const std::string& id, unsigned serial, const Eigen::Vector3d& centre) {
  BrickSnapshot brick;
  brick.id = id;
  brick.type = "kapla";
  brick.serial = serial;
  brick.pose.translation() = centre;
  brick.size = Eigen::Vector3d(test::kKaplaLength, test::kKaplaWidth, test::kKaplaThickness);
  brick.mass = 0.0119;
  return brick;
}

/// A brick resting on a square patch of side 2 `half` [m] centred under
/// `com_above`'s projection shifted by `shift` in x, at height `z`.
SupportGeometry squareSupport(const Eigen::Vector3d& com_above, double half, double shift,
                              double z) {
  SupportGeometry g;
  const double cx = com_above.x() + shift;
  const double cy = com_above.y();
  SupportGeometry::Patch patch;
  patch.supporter = "table";
  patch.polygon = {{cx - half, cy - half, z},
                   {cx + half, cy - half, z},
                   {cx + half, cy + half, z},
                   {cx - half, cy + half, z}};
  g.patches.push_back(patch);
  g.combined_hull = patch.polygon;
  g.com_above = com_above;
  g.margin = half - std::abs(shift);  // the edge nearest to the projection
  return g;
}

TEST(StabilityMarkers, StableBrickOnTheTableHasAGreenRayDownToTheTable) {
  auto world = test::makeWorld(test::optionsFor("com"));
  BrickPlacement placement;
  placement.id = "lone";
  placement.pose.translation() = Eigen::Vector3d(0.1, -0.05, test::kKaplaThickness / 2);
  placement.pose.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  ASSERT_TRUE(world->addBrick(placement).ok);
  test::runFor(world.get(), 0.2);
  BrickSnapshot brick;
  ASSERT_TRUE(world->find("lone", &brick));
  ASSERT_EQ(brick.state, BrickState::kStable);
  SupportGeometryMap supports;
  ASSERT_TRUE(world->supportGeometry("lone", &supports["lone"]));

  const MarkerArray array = makeMarkers({brick}, supports, TableOptions(), "world", ros::Time(1.0));
  ASSERT_FALSE(array.markers.empty());
  EXPECT_EQ(array.markers[0].action, Marker::DELETEALL);
  expectAllFinite(array);

  const Marker* ray = findMarker(array, kComAboveMarkerNamespace, brickMarkerId(brick));
  ASSERT_NE(ray, nullptr) << "no com_above ray";
  EXPECT_EQ(ray->header.frame_id, "world");
  ASSERT_TRUE(ray->type == Marker::LINE_LIST || ray->type == Marker::ARROW);
  ASSERT_GE(ray->points.size(), 2u);
  // From the COM-above (a lone brick: its own centre) straight down to the table top.
  EXPECT_TRUE(toEigen(ray->points[0]).isApprox(brick.com_above, 1e-9));
  EXPECT_NEAR(ray->points[0].x, 0.1, 1e-4);
  EXPECT_NEAR(ray->points[0].y, -0.05, 1e-4);
  EXPECT_NEAR(ray->points[0].z, test::kKaplaThickness / 2, 1e-4);
  EXPECT_EQ(ray->points[1].x, ray->points[0].x);
  EXPECT_EQ(ray->points[1].y, ray->points[0].y);
  EXPECT_NEAR(ray->points[1].z, 0.0, 1e-4);
  EXPECT_GT(ray->scale.x, 0.0);
  EXPECT_TRUE(isGreen(ray->color)) << ray->color.r << " " << ray->color.g << " " << ray->color.b;
  EXPECT_GT(ray->color.a, 0.5f);

  // The patch is the brick's whole bottom face, drawn just above the table.
  const Marker* patches = findMarker(array, kContactMeshMarkerNamespace, patchMarkerId(brick));
  ASSERT_NE(patches, nullptr) << "no contact mesh";
  EXPECT_EQ(patches->type, Marker::TRIANGLE_LIST);
  ASSERT_EQ(patches->points.size() % 3, 0u);
  EXPECT_NEAR(signedTriangleArea(*patches), test::kKaplaLength * test::kKaplaWidth, 1e-6);
  for (const geometry_msgs::Point& p : patches->points) {
    EXPECT_GT(p.z, 0.0) << "not raised above the table";
    EXPECT_LT(p.z, 0.001) << "raised far above the table";
  }
  // The box is opaque: the ray and the mesh inside it show where it is
  // switched off, inside its outline.
  const Marker* box = findMarker(array, kBrickMarkerNamespace, brickMarkerId(brick));
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->color.a, 1.0f);
  const Marker* outline = findMarker(array, kBrickEdgeMarkerNamespace, kBrickEdgesMarkerId);
  ASSERT_NE(outline, nullptr);
  EXPECT_EQ(outline->points.size(), 24u);
}

TEST(StabilityMarkers, RayIsRedOutsideTheSupportAndGreenInside) {
  const BrickSnapshot brick = brickAt("b", 5, {0.3, 0.1, 0.0117});
  for (const auto& [shift, green] : std::vector<std::pair<double, bool>>{
           {0.0, true}, {0.004, true}, {0.011, false}, {0.01, false}}) {  // on the edge: not inside
    SupportGeometryMap supports;
    supports["b"] = squareSupport(brick.pose.translation(), 0.01, shift, 0.0078);
    const MarkerArray array = makeStabilityMarkers({brick}, supports, "world", ros::Time(1.0));
    const Marker* ray = findMarker(array, kComAboveMarkerNamespace, 5);
    ASSERT_NE(ray, nullptr) << shift;
    EXPECT_EQ(isGreen(ray->color), green) << "shift " << shift;
    EXPECT_EQ(isRed(ray->color), !green) << "shift " << shift;
    // It ends at the support height, under the COM-above.
    EXPECT_NEAR(ray->points[1].z, 0.0078, 1e-12);
    EXPECT_EQ(ray->points[1].x, 0.3);
    EXPECT_EQ(ray->points[0].z, 0.0117);
  }
}

TEST(StabilityMarkers, PatchTrianglesCoverEachPatchExactly) {
  const BrickSnapshot brick = brickAt("b", 2, {0.0, 0.0, 0.0117});
  SupportGeometry g;
  g.com_above = Eigen::Vector3d(0.001, 0.002, 0.0117);
  g.margin = 0.003;
  // A convex hexagon and a triangle, counter-clockwise, at two heights.
  SupportGeometry::Patch hexagon{"t0", {}};
  for (int k = 0; k < 6; ++k) {
    const double a = k * M_PI / 3 + 0.2;
    hexagon.polygon.emplace_back(0.01 * std::cos(a) - 0.02, 0.008 * std::sin(a), 0.0078);
  }
  SupportGeometry::Patch triangle{
      "t1", {{0.02, -0.01, 0.0079}, {0.04, -0.01, 0.0079}, {0.03, 0.015, 0.0079}}};
  SupportGeometry::Patch edge{"t2", {{0.0, 0.0, 0.0078}, {0.01, 0.0, 0.0078}}};  // no area
  g.patches = {hexagon, triangle, edge};
  g.combined_hull = {{-0.03, -0.01, 0.00785},
                     {0.04, -0.01, 0.00785},
                     {0.03, 0.015, 0.00785},
                     {-0.03, 0.008, 0.00785}};
  SupportGeometryMap supports{{"b", g}};
  const MarkerArray array = makeStabilityMarkers({brick}, supports, "world", ros::Time(1.0));
  expectAllFinite(array);

  const Marker* patches = findMarker(array, kContactMeshMarkerNamespace, patchMarkerId(brick));
  ASSERT_NE(patches, nullptr);
  ASSERT_EQ(patches->type, Marker::TRIANGLE_LIST);
  // A fan: n - 2 triangles per polygon of n vertices, none for the edge.
  EXPECT_EQ(patches->points.size(), 3u * (4 + 1));
  const double expected = shoelace(hexagon.polygon) + shoelace(triangle.polygon);
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(signedTriangleArea(*patches), expected, 1e-12);
  // Every triangle faces up (so the sum of areas has no cancellation) and
  // lies kContactMeshLift above its own patch.
  for (std::size_t i = 0; i < patches->points.size(); i += 3) {
    Marker one;
    one.points.assign(patches->points.begin() + i, patches->points.begin() + i + 3);
    EXPECT_GT(signedTriangleArea(one), 0.0) << "triangle " << i / 3 << " faces down";
    const double z = i < 12 ? 0.0078 : 0.0079;
    for (const geometry_msgs::Point& p : one.points) EXPECT_NEAR(p.z, z + kContactMeshLift, 1e-12);
  }

  const Marker* hull = findMarker(array, kContactMeshMarkerNamespace, hullMarkerId(brick));
  ASSERT_NE(hull, nullptr);
  EXPECT_NEAR(signedTriangleArea(*hull), shoelace(g.combined_hull), 1e-12);
  EXPECT_LT(hull->color.a, 1.0f) << "the hull must be translucent";
  const auto& pc = patches->color;
  const auto& hc = hull->color;
  EXPECT_GT(std::abs(pc.r - hc.r) + std::abs(pc.g - hc.g) + std::abs(pc.b - hc.b), 0.3f);
}

TEST(StabilityMarkers, IdsComeFromTheSerialAndOnlyDescribedBricksGetThem) {
  std::vector<BrickSnapshot> bricks = {brickAt("a", 3, {0.0, 0.0, 0.0039}),
                                       brickAt("b", 8, {0.2, 0.0, 0.0039}),
                                       brickAt("c", 11, {-0.2, 0.0, 0.0039})};
  SupportGeometryMap supports;
  supports["a"] = squareSupport(bricks[0].pose.translation(), 0.01, 0.0, 0.0);
  supports["b"] = squareSupport(bricks[1].pose.translation(), 0.01, 0.0, 0.0);
  // c: not described (mode none, or a brick in free fall).
  const MarkerArray array = makeMarkers(bricks, supports, TableOptions(), "world", ros::Time(2.0));
  EXPECT_EQ(array.markers[0].action, Marker::DELETEALL);
  EXPECT_EQ(countInNamespace(array, kBrickMarkerNamespace), 1 + 3);
  EXPECT_EQ(countInNamespace(array, kBrickEdgeMarkerNamespace), 1);  // every outline in one
  ASSERT_NE(findMarker(array, kBrickEdgeMarkerNamespace, kBrickEdgesMarkerId), nullptr);
  EXPECT_EQ(findMarker(array, kBrickEdgeMarkerNamespace, kBrickEdgesMarkerId)->points.size(),
            3u * 24u);
  EXPECT_EQ(countInNamespace(array, kComAboveMarkerNamespace), 2);
  EXPECT_EQ(countInNamespace(array, kContactMeshMarkerNamespace), 4);
  EXPECT_NE(findMarker(array, kComAboveMarkerNamespace, 3), nullptr);
  EXPECT_NE(findMarker(array, kComAboveMarkerNamespace, 8), nullptr);
  EXPECT_EQ(findMarker(array, kComAboveMarkerNamespace, 11), nullptr);
  for (int id : {6, 7, 16, 17})
    EXPECT_NE(findMarker(array, kContactMeshMarkerNamespace, id), nullptr) << id;
  for (const Marker& m : array.markers) {
    if (m.action != Marker::ADD) continue;
    EXPECT_EQ(m.header.frame_id, "world");
    EXPECT_EQ(m.header.stamp, ros::Time(2.0));
    EXPECT_EQ(m.pose.orientation.w, 1.0) << m.ns << " " << m.id << ": not a unit quaternion";
  }
}

TEST(StabilityMarkers, NoNaNReachesAMarker) {
  const BrickSnapshot brick = brickAt("b", 1, {0.0, 0.0, 0.0039});
  const SupportGeometry good = squareSupport(brick.pose.translation(), 0.01, 0.0, 0.0);
  auto markersFor = [&](const SupportGeometry& g) {
    return makeStabilityMarkers({brick}, SupportGeometryMap{{"b", g}}, "world", ros::Time(1.0));
  };
  // The control: the good geometry draws a ray, patches and a hull.
  EXPECT_EQ(markersFor(good).markers.size(), 3u);

  SupportGeometry g = good;
  g.com_above.y() = kNaN;
  MarkerArray array = markersFor(g);
  expectAllFinite(array);
  EXPECT_EQ(findMarker(array, kComAboveMarkerNamespace, 1), nullptr);
  EXPECT_NE(findMarker(array, kContactMeshMarkerNamespace, patchMarkerId(brick)), nullptr);

  g = good;
  g.margin = kNaN;
  array = markersFor(g);
  expectAllFinite(array);
  EXPECT_EQ(findMarker(array, kComAboveMarkerNamespace, 1), nullptr);

  g = good;
  g.patches[0].polygon[2].x() = kNaN;
  g.combined_hull[1].z() = std::numeric_limits<double>::infinity();
  array = markersFor(g);
  expectAllFinite(array);
  EXPECT_EQ(findMarker(array, kContactMeshMarkerNamespace, patchMarkerId(brick)), nullptr);
  EXPECT_EQ(findMarker(array, kContactMeshMarkerNamespace, hullMarkerId(brick)), nullptr);

  // A brick in free fall: described, but resting on nothing. No ray, no mesh.
  g = SupportGeometry();
  g.com_above = brick.pose.translation();
  g.margin = -0.01;
  EXPECT_TRUE(markersFor(g).markers.empty());
}

/// The support geometry of every brick of `bricks`, each expected in `state`.
SupportGeometryMap describedAs(const BrickWorld& world, const std::vector<BrickSnapshot>& bricks,
                               BrickState state) {
  SupportGeometryMap supports;
  for (const BrickSnapshot& b : bricks) {
    EXPECT_EQ(b.state, state) << b.id;
    EXPECT_TRUE(world.supportGeometry(b.id, &supports[b.id])) << b.id;
  }
  return supports;
}

/// A contact force with friction 0.5 on the brick, from `other`.
SupportGeometry::ContactForce contactForce(const std::string& other, const Eigen::Vector3d& point,
                                           const Eigen::Vector3d& normal,
                                           const Eigen::Vector3d& force, double friction = 0.5) {
  return SupportGeometry::ContactForce{other, point, normal, force, friction};
}

/// The markers of `brick` in kLeaningMarkerNamespace with id `id`, or null.
const Marker* leaningMarker(const MarkerArray& array, int id) {
  return findMarker(array, kLeaningMarkerNamespace, id);
}

/// Distance of `point` from the line through `apex` along `axis` (unit), and
/// how far along it lies.
std::pair<double, double> radialAndAxial(const Eigen::Vector3d& point, const Eigen::Vector3d& apex,
                                         const Eigen::Vector3d& axis) {
  const Eigen::Vector3d d = point - apex;
  const double along = d.dot(axis);
  return {(d - along * axis).norm(), along};
}

TEST(LeaningMarkers, ArrowsEndAtTheirContactsAndConesShowWhetherFrictionHolds) {
  const BrickSnapshot brick = brickAt("b", 4, {0.0, 0.0, 0.05});
  const double weight = brick.mass * 9.81;
  // Three forces with friction 0.5, each on its own patch: on the bottom
  // face, inside the cone (tangential 0.2 < 0.5 x 0.5); on the side face,
  // inside (0.04 < 0.15); on the bottom face on another body, outside
  // (0.4 > 0.25).
  const double mu = 0.5;
  const std::vector<SupportGeometry::ContactForce> forces = {
      contactForce("table", {0.05, 0.0, 0.046}, Eigen::Vector3d::UnitZ(),
                   weight * Eigen::Vector3d(0.2, 0, 0.5)),
      contactForce("w", {-0.0585, 0.0, 0.05}, Eigen::Vector3d::UnitX(),
                   weight * Eigen::Vector3d(0.3, 0, 0.04)),
      contactForce("t2", {-0.05, 0.0, 0.046}, Eigen::Vector3d::UnitZ(),
                   weight * Eigen::Vector3d(0.4, 0, 0.5))};
  SupportGeometry g;
  g.contact_forces = forces;
  const MarkerArray array =
      makeStabilityMarkers({brick}, SupportGeometryMap{{"b", g}}, "world", ros::Time(1.0));
  expectAllFinite(array);
  EXPECT_EQ(countInNamespace(array, kLeaningMarkerNamespace), 3);

  const Marker* points = leaningMarker(array, contactPointsMarkerId(brick));
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(points->type, Marker::SPHERE_LIST);
  ASSERT_EQ(points->points.size(), 3u);

  // The weight of the brick would draw as 0.3 of its length.
  const double per_newton = 0.3 * test::kKaplaLength / weight;
  EXPECT_NEAR(forceArrowScale(brick), per_newton, 1e-12);
  const Marker* arrows = leaningMarker(array, forceArrowsMarkerId(brick));
  const Marker* cones = leaningMarker(array, frictionConesMarkerId(brick));
  ASSERT_NE(arrows, nullptr);
  ASSERT_NE(cones, nullptr);
  // Per force: a shaft and two barbs; per cone: 4 generators and a rim of
  // 16 segments, 20 segments in all.
  ASSERT_EQ(arrows->points.size(), 3u * 6u);
  ASSERT_EQ(cones->points.size(), 3u * 40u);
  for (std::size_t i = 0; i < forces.size(); ++i) {
    SCOPED_TRACE("force " + std::to_string(i));
    const SupportGeometry::ContactForce& f = forces[i];
    EXPECT_LT((toEigen(points->points[i]) - f.point).norm(), 1e-12);
    // The shaft ends at the contact, its tail is the force back from it.
    const Eigen::Vector3d tail = toEigen(arrows->points[6 * i]);
    const Eigen::Vector3d tip = toEigen(arrows->points[6 * i + 1]);
    EXPECT_LT((tip - f.point).norm(), 1e-12);
    EXPECT_LT((tip - tail - per_newton * f.force).norm(), 1e-12);
    // Every generator leaves the contact at atan(mu) from the outward axis,
    // and every rim point lies on the circle where the cone is as tall as
    // the force's normal part.
    const Eigen::Vector3d outward = -f.normal;
    const double height = per_newton * f.force.dot(f.normal);
    for (std::size_t k = 0; k < 40; ++k) {
      const Eigen::Vector3d point = toEigen(cones->points[40 * i + k]);
      if (k < 8 && k % 2 == 0) {
        EXPECT_LT((point - f.point).norm(), 1e-12) << k;
        continue;
      }
      const auto [radial, axial] = radialAndAxial(point, f.point, outward);
      EXPECT_NEAR(axial, height, 1e-12) << k;
      EXPECT_NEAR(radial, mu * height, 1e-12) << k;
    }
    // The tail lies in the cone's base plane; inside its circle iff the
    // force is inside the friction cone (the first two, not the third).
    const auto [radial, axial] = radialAndAxial(tail, f.point, outward);
    EXPECT_NEAR(axial, height, 1e-12);
    EXPECT_EQ(radial < mu * height, i < 2);
  }
}

TEST(LeaningMarkers, APatchDrawsOneArrowAtItsCentreOfPressure) {
  // Two corners of one face on the table, pressed with 0.25 and 0.75 of the
  // weight, with friction along x: one arrow, the sum of both, ending at
  // the centre of pressure, a quarter of the way from the second corner to
  // the first. A third point on the table along a tilted normal is another
  // patch.
  const BrickSnapshot brick = brickAt("b", 3, {0.0, 0.0, 0.05});
  const double weight = brick.mass * 9.81;
  const Eigen::Vector3d first(-0.04, 0.0, 0.046), second(0.04, 0.0, 0.046);
  const Eigen::Vector3d tilted = Eigen::Vector3d(0.1, 0.0, 1.0).normalized();
  SupportGeometry g;
  g.contact_forces = {contactForce("table", first, Eigen::Vector3d::UnitZ(),
                                   weight * Eigen::Vector3d(0.05, 0, 0.25)),
                      contactForce("table", second, Eigen::Vector3d::UnitZ(),
                                   weight * Eigen::Vector3d(0.05, 0, 0.75)),
                      contactForce("table", {0.0, 0.01, 0.046}, tilted, 0.1 * weight * tilted)};
  const MarkerArray array =
      makeStabilityMarkers({brick}, SupportGeometryMap{{"b", g}}, "world", ros::Time(1.0));
  const Marker* points = leaningMarker(array, contactPointsMarkerId(brick));
  const Marker* arrows = leaningMarker(array, forceArrowsMarkerId(brick));
  ASSERT_NE(points, nullptr);
  ASSERT_NE(arrows, nullptr);
  EXPECT_EQ(points->points.size(), 3u);  // every point is shown
  ASSERT_EQ(arrows->points.size(), 2u * 6u);
  const Eigen::Vector3d pressure_centre = 0.25 * first + 0.75 * second;
  EXPECT_LT((toEigen(arrows->points[1]) - pressure_centre).norm(), 1e-12);
  const Eigen::Vector3d drawn = toEigen(arrows->points[1]) - toEigen(arrows->points[0]);
  EXPECT_LT((drawn - forceArrowScale(brick) * weight * Eigen::Vector3d(0.1, 0, 1.0)).norm(), 1e-12);
}

TEST(LeaningMarkers, NonFiniteForcesAndMasslessBricksDrawNothing) {
  BrickSnapshot brick = brickAt("b", 2, {0.0, 0.0, 0.05});
  const double weight = brick.mass * 9.81;
  SupportGeometry g;
  g.contact_forces = {
      {"table", {0.05, 0.0, 0.046}, Eigen::Vector3d::UnitZ(), {0.0, 0.0, weight}, 0.5},
      {"table", {kNaN, 0.0, 0.046}, Eigen::Vector3d::UnitZ(), {0.0, 0.0, weight}, 0.5},
      {"table", {0.0, 0.0, 0.046}, Eigen::Vector3d::UnitZ(), {0.0, kNaN, weight}, 0.5},
      {"table", {0.0, 0.0, 0.046}, Eigen::Vector3d::UnitZ(), {0.0, 0.0, weight}, kNaN}};
  MarkerArray array =
      makeStabilityMarkers({brick}, SupportGeometryMap{{"b", g}}, "world", ros::Time(1.0));
  expectAllFinite(array);
  const Marker* points = leaningMarker(array, contactPointsMarkerId(brick));
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(points->points.size(), 1u);  // only the finite one
  for (const double mass : {0.0, kNaN, std::numeric_limits<double>::infinity()}) {
    brick.mass = mass;
    array = makeStabilityMarkers({brick}, SupportGeometryMap{{"b", g}}, "world", ros::Time(1.0));
    expectAllFinite(array);
    EXPECT_EQ(countInNamespace(array, kLeaningMarkerNamespace), 0) << mass;
  }
}

TEST(LeaningMarkers, AVFromTheWorldDrawsForcesThatCarryEachPlank) {
  // A V at half its threshold in mode com: each plank's arrows, read back
  // as forces, add up to its weight upwards (statics of a body at rest).
  auto world = test::worldWithFriction("com", 0.5);
  const auto [left, right] = test::vPlanks(0.5 * test::vThresholdAngle(0.5));
  ASSERT_TRUE(world->addBrick(test::at("left", left)).ok);
  ASSERT_TRUE(world->addBrick(test::at("right", right)).ok);
  test::runFor(world.get(), 0.2);
  const std::vector<BrickSnapshot> bricks = world->snapshot();
  const SupportGeometryMap supports = describedAs(*world, bricks, BrickState::kLeaning);
  const MarkerArray array = makeMarkers(bricks, supports, TableOptions(), "world", ros::Time(1.0));
  expectAllFinite(array);
  for (const BrickSnapshot& b : bricks) {
    const Marker* arrows = leaningMarker(array, forceArrowsMarkerId(b));
    ASSERT_NE(arrows, nullptr) << b.id;
    ASSERT_NE(leaningMarker(array, contactPointsMarkerId(b)), nullptr) << b.id;
    ASSERT_NE(leaningMarker(array, frictionConesMarkerId(b)), nullptr) << b.id;
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i + 1 < arrows->points.size(); i += 6)
      total += toEigen(arrows->points[i + 1]) - toEigen(arrows->points[i]);
    const Eigen::Vector3d weight_arrow(0.0, 0.0, 0.3 * test::kKaplaLength);
    EXPECT_LT((total - weight_arrow).norm(), 1e-6 * weight_arrow.norm()) << b.id;
  }
}

// A two-layer tower from the real world: every brick STABLE, with the support
// graph and load the statics give, all of it in the markers and the messages.
TEST(StabilityMarkers, FrozenTowerFromTheWorld) {
  auto world = test::makeWorld(test::optionsFor("com"));
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(world->addBrick(test::towerBrick(i)).ok) << i;
  test::runFor(world.get(), 0.2);
  const std::vector<BrickSnapshot> bricks = world->snapshot();
  ASSERT_EQ(bricks.size(), 4u);
  const SupportGeometryMap supports = describedAs(*world, bricks, BrickState::kStable);
  const MarkerArray array = makeMarkers(bricks, supports, TableOptions(), "world", ros::Time(1.0));
  expectAllFinite(array);
  for (const BrickSnapshot& b : bricks) {
    const bool top = b.id == "t2" || b.id == "t3";
    const Marker* ray = findMarker(array, kComAboveMarkerNamespace, brickMarkerId(b));
    ASSERT_NE(ray, nullptr) << b.id;
    EXPECT_TRUE(isGreen(ray->color)) << b.id;
    EXPECT_NEAR(ray->points[1].z, top ? test::kKaplaThickness : 0.0, 1e-4) << b.id;
    // A top brick rests on two patches, each the square where the planks cross.
    const Marker* patches = findMarker(array, kContactMeshMarkerNamespace, patchMarkerId(b));
    ASSERT_NE(patches, nullptr) << b.id;
    const double face =
        top ? 2 * test::kKaplaWidth * test::kKaplaWidth : test::kKaplaLength * test::kKaplaWidth;
    EXPECT_NEAR(signedTriangleArea(*patches), face, 1e-6) << b.id;
  }
}

// --- boxes, outlines, table and legend -------------------------------------

/// Euclidean distance of two colours in RGB [-].
double colourDistance(const std_msgs::ColorRGBA& a, const std_msgs::ColorRGBA& b) {
  return std::sqrt((a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) +
                   (a.b - b.b) * (a.b - b.b));
}

/// A brick of `look` with marker id `serial`.
BrickSnapshot brickLooking(BrickLook look, unsigned serial) {
  BrickSnapshot brick = brickAt("b" + std::to_string(serial), serial, {0.0, 0.0, 0.0039});
  switch (look) {
    case BrickLook::kFellOff:
      brick.fell_off = true;
      break;
    case BrickLook::kHeld:
      brick.state = BrickState::kHeld;
      break;
    case BrickLook::kLeaning:
      brick.state = BrickState::kLeaning;
      break;
    case BrickLook::kStable:
      brick.state = BrickState::kStable;
      break;
    case BrickLook::kAsleep:
      brick.asleep = true;
      break;
    case BrickLook::kDynamic:
      break;
  }
  EXPECT_EQ(brickLook(brick), look);
  return brick;
}

TEST(BrickMarkers, EveryBoxIsOpaqueInEveryState) {
  std::vector<BrickSnapshot> bricks;
  unsigned serial = 0;
  for (BrickLook look : kAllBrickLooks)
    for (int k = 0; k < 5; ++k) bricks.push_back(brickLooking(look, serial++));
  const MarkerArray array = makeBrickMarkers(bricks, "world", ros::Time(1.0));
  EXPECT_EQ(countInNamespace(array, kBrickMarkerNamespace), 1 + static_cast<int>(bricks.size()));
  for (const BrickSnapshot& brick : bricks) {
    const Marker* box = findMarker(array, kBrickMarkerNamespace, brickMarkerId(brick));
    ASSERT_NE(box, nullptr) << brick.id;
    EXPECT_EQ(box->type, Marker::CUBE);
    EXPECT_EQ(box->color.a, 1.0f) << brick.id << " is not opaque";
    EXPECT_EQ(box->scale.x, brick.size.x());
    EXPECT_EQ(box->scale.z, brick.size.z());
  }
}

TEST(BrickMarkers, OutlinesAreTheTwelveEdgesOfEachBoxInDark) {
  BrickSnapshot turned = brickAt("turned", 7, {0.1, -0.2, 0.0117});
  turned.pose.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 0.1, 1.0).normalized()).toRotationMatrix();
  BrickSnapshot cube = brickAt("cube", 2, {-0.1, 0.05, 0.02});
  cube.size = Eigen::Vector3d(0.04, 0.04, 0.04);
  const std::vector<BrickSnapshot> bricks = {turned, cube};
  const MarkerArray array = makeBrickMarkers(bricks, "world", ros::Time(1.0));
  EXPECT_EQ(countInNamespace(array, kBrickEdgeMarkerNamespace), 1);
  const Marker* edges = findMarker(array, kBrickEdgeMarkerNamespace, kBrickEdgesMarkerId);
  ASSERT_NE(edges, nullptr);
  EXPECT_EQ(edges->type, Marker::LINE_LIST);
  ASSERT_EQ(edges->points.size(), 2u * 24u);
  EXPECT_GT(edges->scale.x, 0.0);
  EXPECT_LT(edges->scale.x, 0.5 * test::kKaplaThickness) << "an outline, not a frame";
  // Per brick, in order, every segment seen in the brick's frame runs along
  // one axis for the whole length of the box (inflated by
  // kBrickEdgeInflation), with both ends at corners; the twelve together
  // cover each axis four times.
  for (std::size_t b = 0; b < bricks.size(); ++b) {
    SCOPED_TRACE(bricks[b].id);
    const Eigen::Isometry3d& pose = bricks[b].pose;
    const Eigen::Vector3d half =
        0.5 * bricks[b].size + Eigen::Vector3d::Constant(kBrickEdgeInflation);
    int along[3] = {0, 0, 0};
    for (std::size_t i = 24 * b; i < 24 * (b + 1); i += 2) {
      const Eigen::Vector3d from = pose.inverse() * toEigen(edges->points[i]);
      const Eigen::Vector3d to = pose.inverse() * toEigen(edges->points[i + 1]);
      for (const Eigen::Vector3d& end : {from, to})
        EXPECT_LT((end.cwiseAbs() - half).norm(), 1e-12) << "not at a corner";
      const Eigen::Vector3d d = (to - from).cwiseAbs();
      int axis = 0;
      d.maxCoeff(&axis);
      EXPECT_NEAR(d[axis], 2.0 * half[axis], 1e-12);
      EXPECT_NEAR(d.sum() - d[axis], 0.0, 1e-12);
      ++along[axis];
    }
    EXPECT_EQ(along[0], 4);
    EXPECT_EQ(along[1], 4);
    EXPECT_EQ(along[2], 4);
  }
  // Darker than the darkest wood it outlines.
  const float brightness = edges->color.r + edges->color.g + edges->color.b;
  for (BrickLook look : kAllBrickLooks) {
    const std_msgs::ColorRGBA tint = brickColor(look);
    EXPECT_LT(brightness, 0.5f * (tint.r + tint.g + tint.b)) << lookName(look);
  }
  // No bricks, no outline (RViz flags an empty LINE_LIST).
  EXPECT_EQ(
      countInNamespace(makeBrickMarkers({}, "world", ros::Time(1.0)), kBrickEdgeMarkerNamespace),
      0);
}

TEST(BrickMarkers, NeighbouringBricksGetDifferentColoursThatStayTheSame) {
  // Bricks placed one after another (neighbours in a layer, a brick and the
  // one on it) differ in tone; the same brick keeps its tone.
  for (BrickLook look : kAllBrickLooks) {
    for (unsigned serial = 0; serial < 200; ++serial) {
      const std_msgs::ColorRGBA a = brickColor(brickLooking(look, serial));
      for (unsigned step : {1u, 2u}) {
        const std_msgs::ColorRGBA b = brickColor(brickLooking(look, serial + step));
        EXPECT_GT(colourDistance(a, b), 0.03) << lookName(look) << " " << serial << "+" << step;
      }
      EXPECT_EQ(colourDistance(a, brickColor(brickLooking(look, serial))), 0.0);
    }
  }
  // Through the marker array too, two planks of a tower layer.
  const std::vector<BrickSnapshot> layer = {brickLooking(BrickLook::kStable, 0),
                                            brickLooking(BrickLook::kStable, 1)};
  const MarkerArray array = makeBrickMarkers(layer, "world", ros::Time(1.0));
  const Marker* first = findMarker(array, kBrickMarkerNamespace, 0);
  const Marker* second = findMarker(array, kBrickMarkerNamespace, 1);
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  EXPECT_GT(colourDistance(first->color, second->color), 0.03);
}

TEST(BrickMarkers, EachStateHasItsTintAndTheWoodToneNeverBlursIt) {
  for (BrickLook a : kAllBrickLooks) {
    EXPECT_EQ(brickColor(a).a, 1.0f);
    for (BrickLook b : kAllBrickLooks) {
      if (a == b) continue;
      EXPECT_GT(colourDistance(brickColor(a), brickColor(b)), 0.25)
          << lookName(a) << " and " << lookName(b) << " are too close";
    }
  }
  // The wood tone lightens a tint by up to kWoodToneSpread: no channel clips.
  for (BrickLook look : kAllBrickLooks) {
    const std_msgs::ColorRGBA tint = brickColor(look);
    EXPECT_LE(std::max({tint.r, tint.g, tint.b}) * (1.0 + kWoodToneSpread), 1.0) << lookName(look);
  }
  // Stable is wood: warm (red over green over blue).
  const std_msgs::ColorRGBA pine = brickColor(BrickLook::kStable);
  EXPECT_GT(pine.r, pine.g);
  EXPECT_GT(pine.g, pine.b);
  // Dynamic is blue-grey, fell off is red.
  EXPECT_GT(brickColor(BrickLook::kDynamic).b, brickColor(BrickLook::kDynamic).r);
  EXPECT_TRUE(isRed(brickColor(BrickLook::kFellOff)));
  // Whatever a brick's tone, the nearest tint is its own state's.
  for (BrickLook look : kAllBrickLooks) {
    for (unsigned serial = 0; serial < 500; ++serial) {
      const std_msgs::ColorRGBA colour = brickColor(brickLooking(look, serial));
      for (BrickLook other : kAllBrickLooks) {
        if (other == look) continue;
        EXPECT_LT(colourDistance(colour, brickColor(look)),
                  colourDistance(colour, brickColor(other)))
            << lookName(look) << " brick " << serial << " looks " << lookName(other);
      }
    }
  }
}

TEST(StabilityMarkers, RayRunsFromTheCarriedComAboveDownToTheSupportAndReads) {
  // A plank low in a tower: its COM-above (of it and its load) lies 10 cm
  // up, far outside the plank, over a point off its centre.
  const BrickSnapshot brick = brickAt("low", 4, {0.0, 0.047, 0.0117});
  const Eigen::Vector3d com_above(0.003, 0.045, 0.1);
  SupportGeometryMap supports;
  supports["low"] = squareSupport(com_above, 0.0117, 0.0, 0.0078);
  const MarkerArray array = makeStabilityMarkers({brick}, supports, "world", ros::Time(1.0));
  const Marker* ray = findMarker(array, kComAboveMarkerNamespace, brickMarkerId(brick));
  ASSERT_NE(ray, nullptr);
  ASSERT_EQ(ray->type, Marker::LINE_LIST);
  ASSERT_EQ(ray->points.size(), 6u);  // the ray and the two arms of the foot
  EXPECT_LT((toEigen(ray->points[0]) - com_above).norm(), 1e-12);
  EXPECT_LT((toEigen(ray->points[1]) - Eigen::Vector3d(0.003, 0.045, 0.0078)).norm(), 1e-12);
  // The foot: a cross in the support plane centred under the COM-above,
  // wider than a plank so that it shows on both sides of the one it lies on.
  for (std::size_t i = 2; i < 6; i += 2) {
    const Eigen::Vector3d a = toEigen(ray->points[i]);
    const Eigen::Vector3d b = toEigen(ray->points[i + 1]);
    EXPECT_NEAR(a.z(), 0.0078, 1e-12);
    EXPECT_NEAR(b.z(), 0.0078, 1e-12);
    EXPECT_LT((0.5 * (a + b) - toEigen(ray->points[1])).norm(), 1e-12);
    EXPECT_GT((b - a).norm(), test::kKaplaWidth);
  }
  // Thick enough to read as a line at tower scale, thinner than a plank.
  EXPECT_GE(ray->scale.x, 0.002);
  EXPECT_LT(ray->scale.x, test::kKaplaThickness);
  EXPECT_EQ(ray->color.a, 1.0f);
}

TEST(TableMarkers, TopMatchesTheTableOptionsAndTheFloorLiesWhereBricksFall) {
  TableOptions table;
  table.size = Eigen::Vector2d(0.9, 0.5);
  table.thickness = 0.02;
  table.height = 0.6;
  const MarkerArray array = makeTableMarkers(table, "world", ros::Time(1.0));
  expectAllFinite(array);
  EXPECT_EQ(countInNamespace(array, kTableMarkerNamespace), static_cast<int>(array.markers.size()));
  const Marker* top = findMarker(array, kTableMarkerNamespace, 0);
  ASSERT_NE(top, nullptr);
  EXPECT_EQ(top->type, Marker::CUBE);
  EXPECT_EQ(top->header.frame_id, "world");
  EXPECT_DOUBLE_EQ(top->scale.x, 0.9);
  EXPECT_DOUBLE_EQ(top->scale.y, 0.5);
  EXPECT_DOUBLE_EQ(top->scale.z, 0.02);
  // Its upper face is the plane z = 0 bricks stand on, centred on the origin.
  EXPECT_DOUBLE_EQ(top->pose.position.x, 0.0);
  EXPECT_DOUBLE_EQ(top->pose.position.y, 0.0);
  EXPECT_DOUBLE_EQ(top->pose.position.z + 0.5 * top->scale.z, 0.0);
  EXPECT_EQ(top->color.a, 1.0f);
  // Neither wood nor a tint: every brick stands out on it.
  for (BrickLook look : kAllBrickLooks)
    EXPECT_GT(colourDistance(top->color, brickColor(look)), 0.2) << lookName(look);

  // The floor: its upper face `height` below the top, under all of the table.
  const Marker* floor = findMarker(array, kTableMarkerNamespace, 1);
  ASSERT_NE(floor, nullptr);
  EXPECT_NEAR(floor->pose.position.z + 0.5 * floor->scale.z, -0.6, 1e-12);
  EXPECT_GT(floor->scale.x, 0.9);
  EXPECT_GT(floor->scale.y, 0.5);
  // Four legs from the floor to the underside of the top, inside its outline.
  for (int id = 2; id < 6; ++id) {
    const Marker* leg = findMarker(array, kTableMarkerNamespace, id);
    ASSERT_NE(leg, nullptr) << id;
    EXPECT_NEAR(leg->pose.position.z + 0.5 * leg->scale.z, -0.02, 1e-12) << id;
    EXPECT_NEAR(leg->pose.position.z - 0.5 * leg->scale.z, -0.6, 1e-12) << id;
    EXPECT_LE(std::abs(leg->pose.position.x) + 0.5 * leg->scale.x, 0.45 + 1e-12) << id;
    EXPECT_LE(std::abs(leg->pose.position.y) + 0.5 * leg->scale.y, 0.25 + 1e-12) << id;
  }

  // A table that is not one draws nothing rather than a NaN.
  for (double bad : {kNaN, 0.0, -1.0}) {
    TableOptions broken = table;
    broken.size.x() = bad;
    EXPECT_TRUE(makeTableMarkers(broken, "world", ros::Time(1.0)).markers.empty()) << bad;
    broken = table;
    broken.height = bad;
    EXPECT_TRUE(makeTableMarkers(broken, "world", ros::Time(1.0)).markers.empty()) << bad;
  }
}

TEST(LegendMarkers, OneLinePerStateInItsTintThenTheStabilityMarkers) {
  const TableOptions table;
  const MarkerArray array = makeLegendMarkers(table, "world", ros::Time(1.0));
  expectAllFinite(array);
  const std::vector<LegendEntry> entries = legendEntries();
  ASSERT_EQ(array.markers.size(), entries.size());
  // One line per look: its name, in its tint.
  for (BrickLook look : kAllBrickLooks) {
    const std::string name = std::string(lookName(look)) + ":";
    int found = 0;
    for (const Marker& line : array.markers) {
      if (line.text.rfind(name, 0) != 0) continue;
      ++found;
      EXPECT_EQ(colourDistance(line.color, brickColor(look)), 0.0) << name;
    }
    EXPECT_EQ(found, 1) << name;
  }
  // And a line for each marker of the stability layer, in that marker's
  // colour (made opaque: text), taken from markers drawn here.
  const BrickSnapshot brick = brickAt("b", 1, {0.0, 0.0, 0.05});
  SupportGeometry geometry = squareSupport(brick.pose.translation(), 0.01, 0.0, 0.046);
  geometry.contact_forces = {
      contactForce("table", {0.0, 0.0, 0.046}, Eigen::Vector3d::UnitZ(), {0.02, 0.0, 0.1})};
  const MarkerArray drawn =
      makeStabilityMarkers({brick}, SupportGeometryMap{{"b", geometry}}, "world", ros::Time(1.0));
  const Marker* patches = findMarker(drawn, kContactMeshMarkerNamespace, patchMarkerId(brick));
  const Marker* arrows = findMarker(drawn, kLeaningMarkerNamespace, forceArrowsMarkerId(brick));
  const Marker* cones = findMarker(drawn, kLeaningMarkerNamespace, frictionConesMarkerId(brick));
  ASSERT_TRUE(patches && arrows && cones);
  auto line_with = [&](const std::string& word, const std_msgs::ColorRGBA& colour) {
    for (const Marker& line : array.markers)
      if (line.text.find(word) != std::string::npos && colourDistance(line.color, colour) < 1e-6)
        return true;
    return false;
  };
  EXPECT_TRUE(line_with("ray", comAboveColor(1.0)));
  EXPECT_TRUE(line_with("ray", comAboveColor(-1.0)));
  EXPECT_TRUE(line_with("contacts", patches->color));
  EXPECT_TRUE(line_with("force", arrows->color));
  EXPECT_TRUE(line_with("friction", cones->color));
  EXPECT_TRUE(std::any_of(array.markers.begin(), array.markers.end(), [](const Marker& line) {
    return line.text.find("'bricks'") != std::string::npos;
  })) << "no line says how to see inside the stack";

  // View-facing text in a column over the table, top line first.
  for (std::size_t i = 0; i < array.markers.size(); ++i) {
    const Marker& line = array.markers[i];
    EXPECT_EQ(line.ns, kLegendMarkerNamespace);
    EXPECT_EQ(line.id, static_cast<int>(i));
    EXPECT_EQ(line.type, Marker::TEXT_VIEW_FACING);
    EXPECT_EQ(line.text, entries[i].text);
    EXPECT_FALSE(line.text.empty());
    EXPECT_GT(line.scale.z, 0.0);
    EXPECT_EQ(line.color.a, 1.0f);
    EXPECT_LE(std::abs(line.pose.position.x), 0.5 * table.size.x());
    EXPECT_LE(std::abs(line.pose.position.y), 0.5 * table.size.y());
    EXPECT_GT(line.pose.position.z, 0.0) << "below the table top";
    if (i > 0) {
      EXPECT_EQ(line.pose.position.x, array.markers[0].pose.position.x);
      EXPECT_NEAR(array.markers[i - 1].pose.position.z - line.pose.position.z, kLegendLineSpacing,
                  1e-12);
    }
  }
  // On a small table the legend stays over it.
  TableOptions small;
  small.size = Eigen::Vector2d(0.2, 0.1);
  for (const Marker& line : makeLegendMarkers(small, "world", ros::Time(1.0)).markers) {
    EXPECT_LE(std::abs(line.pose.position.x), 0.1 + 1e-12);
    EXPECT_LE(std::abs(line.pose.position.y), 0.05 + 1e-12);
  }
}

TEST(LegendMarkers, TitleStandsOverTheTableCentreAboveTheLegend) {
  const TableOptions table;
  LegendStyle style;
  style.title = "mode equilibrium";
  const MarkerArray array = makeLegendMarkers(table, "world", ros::Time(1.0), style);
  expectAllFinite(array);
  const Marker* title = findMarker(array, kLegendMarkerNamespace, kLegendTitleMarkerId);
  ASSERT_NE(title, nullptr);
  EXPECT_EQ(title->type, Marker::TEXT_VIEW_FACING);
  EXPECT_EQ(title->text, "mode equilibrium");
  EXPECT_EQ(title->color.a, 1.0f);
  // Inside the table's footprint, over its centre, where the structure stands.
  EXPECT_LE(std::abs(title->pose.position.x), 0.5 * table.size.x());
  EXPECT_LE(std::abs(title->pose.position.y), 0.5 * table.size.y());
  // Above the table top, and with its whole height above the legend's
  // first line (text is centred on its position).
  const Marker& first = array.markers[0];
  EXPECT_GT(title->pose.position.z - 0.5 * title->scale.z,
            first.pose.position.z + 0.5 * first.scale.z);
  // Larger than a line of the legend: it names the table from afar.
  EXPECT_GE(title->scale.z, 2.0 * first.scale.z);
  // No title: the lines alone.
  EXPECT_EQ(makeLegendMarkers(table, "world", ros::Time(1.0)).markers.size(),
            legendEntries().size());
}

TEST(LegendMarkers, SizesAndOffsetsScaleWithTheTableAndTheStyle) {
  const TableOptions table;
  LegendStyle style;
  style.title = "mode com";
  const MarkerArray one = makeLegendMarkers(table, "world", ros::Time(1.0), style);
  // Twice the scale, or a table twice as large: every height, offset and
  // spacing twice as large, the column still over the table.
  LegendStyle doubled = style;
  doubled.scale = 2.0;
  TableOptions large = table;
  large.size *= 2.0;
  for (const MarkerArray& two : {makeLegendMarkers(table, "world", ros::Time(1.0), doubled),
                                 makeLegendMarkers(large, "world", ros::Time(1.0), style)}) {
    ASSERT_EQ(two.markers.size(), one.markers.size());
    for (std::size_t i = 0; i < one.markers.size(); ++i) {
      const Marker& a = one.markers[i];
      const Marker& b = two.markers[i];
      EXPECT_EQ(a.id, b.id);
      EXPECT_NEAR(b.scale.z, 2.0 * a.scale.z, 1e-12) << i;
      EXPECT_NEAR(b.pose.position.z, 2.0 * a.pose.position.z, 1e-12) << i;
      // The default offsets (0.2, 0.12) doubled are still inside 0.6 by 0.4.
      EXPECT_NEAR(b.pose.position.x, 2.0 * a.pose.position.x, 1e-12) << i;
      EXPECT_NEAR(b.pose.position.y, 2.0 * a.pose.position.y, 1e-12) << i;
    }
  }
  // The default table is the reference: its legend keeps the constants.
  EXPECT_NEAR(legendScale(table, LegendStyle()), 1.0, 1e-12);
  EXPECT_NEAR(one.markers[0].scale.z, kLegendTextHeight, 1e-12);
  EXPECT_NEAR(one.markers[0].pose.position.z, kLegendTop, 1e-12);
  // A scale that is not one counts as 1.
  for (double bad : {kNaN, 0.0, -2.0}) {
    LegendStyle broken;
    broken.scale = bad;
    EXPECT_NEAR(legendScale(table, broken), 1.0, 1e-12) << bad;
  }
  // A huge scale still keeps the column over the table's corner at most.
  LegendStyle huge;
  huge.scale = 10.0;
  for (const Marker& line : makeLegendMarkers(table, "world", ros::Time(1.0), huge).markers) {
    EXPECT_LE(std::abs(line.pose.position.x), 0.5 * table.size.x() + 1e-12);
    EXPECT_LE(std::abs(line.pose.position.y), 0.5 * table.size.y() + 1e-12);
  }
}

TEST(AllMarkers, TableAndLegendComeWithEveryArrayAfterItsDeleteAll) {
  // An empty scene still shows the table and the legend; with bricks, they
  // come after the DELETEALL that would otherwise remove them.
  for (const std::vector<BrickSnapshot>& bricks :
       {std::vector<BrickSnapshot>{},
        std::vector<BrickSnapshot>{brickLooking(BrickLook::kStable, 0)}}) {
    const MarkerArray array =
        makeMarkers(bricks, SupportGeometryMap(), TableOptions(), "world", ros::Time(1.0));
    ASSERT_FALSE(array.markers.empty());
    EXPECT_EQ(array.markers[0].action, Marker::DELETEALL);
    for (std::size_t i = 1; i < array.markers.size(); ++i)
      EXPECT_EQ(array.markers[i].action, Marker::ADD) << i;
    EXPECT_EQ(countInNamespace(array, kTableMarkerNamespace), 6);
    EXPECT_EQ(countInNamespace(array, kLegendMarkerNamespace),
              static_cast<int>(legendEntries().size()));
    EXPECT_EQ(countInNamespace(array, kBrickEdgeMarkerNamespace), bricks.empty() ? 0 : 1);
  }
}

TEST(AllMarkers, NoNaNReachesAnyMarker) {
  // Bricks and support geometry with NaN and Inf in every field the markers
  // read, next to a good brick, and a table with a NaN: RViz would drop the
  // whole array for one of them.
  std::vector<BrickSnapshot> bricks = {
      brickAt("good", 0, {0.0, 0.0, 0.0039}), brickAt("pose", 1, {kNaN, 0.0, 0.0039}),
      brickAt("size", 2, {0.1, 0.0, 0.0039}), brickAt("rotation", 3, {0.2, 0.0, 0.0039}),
      brickAt("mass", 4, {0.3, 0.0, 0.0039})};
  bricks[2].size.y() = std::numeric_limits<double>::infinity();
  bricks[3].pose.linear()(0, 1) = kNaN;
  bricks[4].mass = kNaN;
  SupportGeometryMap supports;
  for (const BrickSnapshot& b : bricks) {
    const Eigen::Vector3d centre = b.pose.translation().allFinite()
                                       ? Eigen::Vector3d(b.pose.translation())
                                       : Eigen::Vector3d(0.0, 0.0, 0.0039);
    supports[b.id] = squareSupport(centre, 0.01, 0.0, 0.0);
  }
  supports["good"].contact_forces = {
      contactForce("table", {0.0, 0.0, 0.0}, Eigen::Vector3d::UnitZ(), {kNaN, 0.0, 0.1})};
  supports["mass"].contact_forces = {
      contactForce("table", {0.3, 0.0, 0.0}, Eigen::Vector3d::UnitZ(), {0.0, 0.0, 0.1})};
  supports["pose"].com_above.x() = kNaN;
  supports["size"].margin = std::numeric_limits<double>::infinity();
  supports["rotation"].combined_hull[0].y() = kNaN;
  TableOptions table;
  table.thickness = kNaN;
  const MarkerArray array = makeMarkers(bricks, supports, table, "world", ros::Time(1.0));
  expectAllFinite(array);
  for (const Marker& m : array.markers) {
    for (float c : {m.color.r, m.color.g, m.color.b, m.color.a})
      EXPECT_TRUE(std::isfinite(c)) << m.ns << " " << m.id;
    EXPECT_TRUE(std::isfinite(m.pose.orientation.x) && std::isfinite(m.pose.orientation.y) &&
                std::isfinite(m.pose.orientation.z))
        << m.ns << " " << m.id;
  }
  // The good brick is all there; the broken ones' boxes are left out.
  EXPECT_NE(findMarker(array, kBrickMarkerNamespace, 0), nullptr);
  EXPECT_NE(findMarker(array, kComAboveMarkerNamespace, 0), nullptr);
  for (int id : {1, 2, 3}) EXPECT_EQ(findMarker(array, kBrickMarkerNamespace, id), nullptr) << id;
  const Marker* outlines = findMarker(array, kBrickEdgeMarkerNamespace, kBrickEdgesMarkerId);
  ASSERT_NE(outlines, nullptr);
  EXPECT_EQ(outlines->points.size(), 2u * 24u);  // the good brick's and the massless one's
  EXPECT_EQ(countInNamespace(array, kTableMarkerNamespace), 0);
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
