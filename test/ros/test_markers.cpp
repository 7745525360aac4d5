// ~markers as a pure function of snapshots and support geometry: boxes,
// COM-above rays, contact meshes and contact forces, checked against
// geometry computed here (areas, heights, cone angles) and against a real
// world in mode com.
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

  const MarkerArray array = makeMarkers({brick}, supports, "world", ros::Time(1.0), 0.45f);
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
  // Boxes are translucent so that the ray and the mesh inside them show.
  const Marker* box = findMarker(array, kBrickMarkerNamespace, brickMarkerId(brick));
  ASSERT_NE(box, nullptr);
  EXPECT_FLOAT_EQ(box->color.a, 0.45f);
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
  const MarkerArray array = makeMarkers(bricks, supports, "world", ros::Time(2.0), 1.0f);
  EXPECT_EQ(array.markers[0].action, Marker::DELETEALL);
  EXPECT_EQ(countInNamespace(array, kBrickMarkerNamespace), 1 + 3);
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
  const MarkerArray array = makeMarkers(bricks, supports, "world", ros::Time(1.0), 0.45f);
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
  const MarkerArray array = makeMarkers(bricks, supports, "world", ros::Time(1.0), 0.45f);
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

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
