#include "brick_stack_sim/ros/brick_markers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/types/table_solid.h"
#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {

int brickMarkerId(const BrickSnapshot& brick) { return static_cast<int>(brick.serial); }

int edgeMarkerId(const BrickSnapshot& brick) { return edgeMarkerId(brick.serial); }

int edgeMarkerId(unsigned serial) { return static_cast<int>(serial / kBricksPerEdgeMarker); }

visualization_msgs::Marker makeEdgeMarker(int id, const std::string& frame_id,
                                          const ros::Time& stamp) {
  using visualization_msgs::Marker;
  Marker edges = newMarker(frame_id, stamp, kBrickEdgeMarkerNamespace, id, Marker::LINE_LIST);
  edges.scale.x = kBrickEdgeWidth;         // LINE_LIST: only x, the line width
  edges.color = rgb(0.16f, 0.10f, 0.05f);  // dark walnut: a seam, not a colour of its own
  return edges;
}

namespace {

bool drawable(const BrickSnapshot& brick) {
  return brick.pose.matrix().allFinite() && brick.size.allFinite();
}

/// Drawn as bricks were before shapes, from `size` alone: bit for bit the
/// same markers for every box brick.
bool plainBox(const BrickSnapshot& brick) {
  if (!brick.solid || brick.solid->parts.empty()) return true;
  const ConvexPart& part = brick.solid->parts.front();
  return brick.solid->parts.size() == 1 && part.isBox() &&
         part.pose.matrix() == Eigen::Matrix4d::Identity();
}

/// The part's frame in the world; an identity part pose keeps the solid's
/// pose bit for bit (a product with it may turn -0 into +0).
Eigen::Isometry3d partPose(const Eigen::Isometry3d& solid_pose, const ConvexPart& part) {
  return part.pose.matrix() == Eigen::Matrix4d::Identity() ? solid_pose : solid_pose * part.pose;
}

bool finitePolyhedron(const ConvexPolyhedron& polyhedron) {
  for (const Eigen::Vector3d& v : polyhedron.vertices)
    if (!v.allFinite()) return false;
  return true;
}

/// Every number that reaches a marker of the part is finite, and it has a
/// body: a box or a cylinder of positive size, or a hull with a face.
bool drawablePart(const ConvexPart& part, const Eigen::Isometry3d& pose) {
  if (!pose.matrix().allFinite()) return false;
  if (part.isBox()) return part.box_half_extents.allFinite();
  if (part.isCylinder())
    return std::isfinite(part.cylinder_radius) && std::isfinite(part.cylinder_length) &&
           part.cylinder_length > 0.0;
  return !part.polyhedron.faces.empty() && finitePolyhedron(part.polyhedron);
}

void appendBoxEdges(const OrientedBox& box, std::vector<geometry_msgs::Point>* lines) {
  const std::array<Eigen::Vector3d, 8> corner = corners(box);
  // Corner i's bits say which side of each axis it lies on (corners()), so
  // the corners i and i + bit differ along one axis: every edge once.
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) appendSegment(corner[i], corner[i | bit], lines);
}

void appendRims(const ConvexPart& part, const Eigen::Isometry3d& pose, double inflation,
                std::vector<geometry_msgs::Point>* lines) {
  const double radius = part.cylinder_radius + inflation;
  for (double z :
       {-0.5 * part.cylinder_length - inflation, 0.5 * part.cylinder_length + inflation}) {
    auto rim = [&](int i) {
      const double angle = 2.0 * M_PI * i / kCylinderRimSegments;
      return pose * Eigen::Vector3d(radius * std::cos(angle), radius * std::sin(angle), z);
    };
    for (int i = 0; i < kCylinderRimSegments; ++i) appendSegment(rim(i), rim(i + 1), lines);
  }
}

/// Each vertex moved out so that it lies at least `inflation` outside every
/// face it is on: along the mean of those faces' normals, as far as the face
/// most across that mean needs (a box corner moves by `inflation` on each
/// axis). The factor is capped where a vertex's faces nearly fold back.
std::vector<Eigen::Vector3d> inflatedVertices(const ConvexPolyhedron& polyhedron,
                                              double inflation) {
  const std::size_t n = polyhedron.vertices.size();
  std::vector<Eigen::Vector3d> direction(n, Eigen::Vector3d::Zero());
  for (const ConvexPolyhedron::Face& face : polyhedron.faces)
    for (int i : face.loop) direction[i] += face.normal;
  for (Eigen::Vector3d& d : direction)
    if (d.norm() > 0.0) d.normalize();
  std::vector<double> least(n, 1.0);
  for (const ConvexPolyhedron::Face& face : polyhedron.faces)
    for (int i : face.loop) least[i] = std::min(least[i], direction[i].dot(face.normal));
  std::vector<Eigen::Vector3d> moved(n);
  for (std::size_t i = 0; i < n; ++i)
    moved[i] = polyhedron.vertices[i] + direction[i] * (inflation / std::max(least[i], 0.2));
  return moved;
}

}  // namespace

void appendPartOutline(const ConvexPart& part, const Eigen::Isometry3d& solid_pose,
                       double inflation, std::vector<geometry_msgs::Point>* lines) {
  const Eigen::Isometry3d pose = partPose(solid_pose, part);
  if (!drawablePart(part, pose)) return;
  if (part.isBox()) {
    appendBoxEdges(OrientedBox{pose, part.box_half_extents + Eigen::Vector3d::Constant(inflation)},
                   lines);
  } else if (part.isCylinder()) {
    appendRims(part, pose, inflation, lines);
  } else {
    const std::vector<Eigen::Vector3d> moved = inflatedVertices(part.polyhedron, inflation);
    for (const std::array<int, 2>& edge : part.polyhedron.edges)
      appendSegment(pose * moved[edge[0]], pose * moved[edge[1]], lines);
  }
}

void appendEdges(const BrickSnapshot& brick, std::vector<geometry_msgs::Point>* lines) {
  if (!drawable(brick)) return;
  if (plainBox(brick)) {
    appendBoxEdges(
        OrientedBox{brick.pose, 0.5 * brick.size + Eigen::Vector3d::Constant(kBrickEdgeInflation)},
        lines);
    return;
  }
  for (const ConvexPart& part : brick.solid->parts)
    appendPartOutline(part, brick.pose, kBrickEdgeInflation, lines);
}

namespace {

/// Appends the triangles of `polyhedron`'s faces carried by `placement`,
/// counter-clockwise fans, so that every triangle faces out as RViz lights it.
void appendFaceTriangles(const ConvexPolyhedron& polyhedron, const Eigen::Isometry3d& placement,
                         std::vector<geometry_msgs::Point>* points) {
  for (const ConvexPolyhedron::Face& face : polyhedron.faces)
    for (std::size_t i = 1; i + 1 < face.loop.size(); ++i)
      for (int vertex : {face.loop[0], face.loop[i], face.loop[i + 1]})
        points->push_back(toPointMsg(placement * polyhedron.vertices[vertex]));
}

/// A compound brick's parts as one TRIANGLE_LIST in the brick's frame: one
/// marker per brick, however many parts.
bool compoundBodyMarker(const ConvexSolid& solid, const Eigen::Isometry3d& solid_pose,
                        visualization_msgs::Marker* marker) {
  std::vector<geometry_msgs::Point> points;
  for (const ConvexPart& part : solid.parts)
    if (drawablePart(part, partPose(solid_pose, part)))
      appendFaceTriangles(part.polyhedron, part.pose, &points);
  if (points.empty() || !solid_pose.matrix().allFinite()) return false;
  marker->type = visualization_msgs::Marker::TRIANGLE_LIST;
  marker->scale = toVectorMsg(Eigen::Vector3d::Ones());  // the points are taken as they are
  marker->points = std::move(points);
  marker->pose = toPoseMsg(solid_pose);
  return true;
}

}  // namespace

bool partBodyMarker(const ConvexPart& part, const Eigen::Isometry3d& solid_pose,
                    visualization_msgs::Marker* marker) {
  using visualization_msgs::Marker;
  const Eigen::Isometry3d pose = partPose(solid_pose, part);
  if (!drawablePart(part, pose)) return false;
  if (part.isBox()) {
    marker->type = Marker::CUBE;
    marker->scale = toVectorMsg(2.0 * part.box_half_extents);
  } else if (part.isCylinder()) {
    marker->type = Marker::CYLINDER;  // RViz's cylinder stands along its z, as the part's
    const double diameter = 2.0 * part.cylinder_radius;
    marker->scale = toVectorMsg(Eigen::Vector3d(diameter, diameter, part.cylinder_length));
  } else {
    std::vector<geometry_msgs::Point> points;
    appendFaceTriangles(part.polyhedron, Eigen::Isometry3d::Identity(), &points);
    if (points.empty()) return false;  // RViz refuses an empty TRIANGLE_LIST
    marker->type = Marker::TRIANGLE_LIST;
    marker->scale = toVectorMsg(Eigen::Vector3d::Ones());  // the points are taken as they are
    marker->points = std::move(points);
  }
  marker->pose = toPoseMsg(pose);
  if (marker->type != Marker::TRIANGLE_LIST) marker->points.clear();
  return true;
}

std::vector<visualization_msgs::Marker> solidBodyMarkers(const ConvexSolid* solid,
                                                         const Eigen::Vector3d& size,
                                                         const Eigen::Isometry3d& pose,
                                                         const std_msgs::ColorRGBA& color) {
  std::vector<visualization_msgs::Marker> markers;
  const ConvexSolid box = boxSolid(0.5 * size);
  const ConvexSolid& drawn = solid && !solid->parts.empty() ? *solid : box;
  for (const ConvexPart& part : drawn.parts) {
    visualization_msgs::Marker marker;
    if (!partBodyMarker(part, pose, &marker)) continue;
    marker.color = color;
    markers.push_back(std::move(marker));
  }
  return markers;
}

void appendBodyMarkers(const BrickSnapshot& brick, const std::string& frame_id,
                       const ros::Time& stamp, visualization_msgs::MarkerArray* array) {
  using visualization_msgs::Marker;
  if (!drawable(brick)) return;
  if (plainBox(brick)) {
    Marker box =
        newMarker(frame_id, stamp, kBrickMarkerNamespace, brickMarkerId(brick), Marker::CUBE);
    box.pose = toPoseMsg(brick.pose);
    box.scale = toVectorMsg(brick.size);
    box.color = brickColor(brick);
    array->markers.push_back(std::move(box));
    return;
  }
  Marker body =
      newMarker(frame_id, stamp, kBrickMarkerNamespace, brickMarkerId(brick), Marker::CUBE);
  const bool drawn = brick.solid->parts.size() == 1
                         ? partBodyMarker(brick.solid->parts[0], brick.pose, &body)
                         : compoundBodyMarker(*brick.solid, brick.pose, &body);
  if (!drawn) return;
  body.color = brickColor(brick);
  array->markers.push_back(std::move(body));
}

visualization_msgs::MarkerArray makeBrickMarkers(const std::vector<BrickSnapshot>& bricks,
                                                 const std::string& frame_id,
                                                 const ros::Time& stamp) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray array;
  array.markers.reserve(bricks.size() + 2);
  Marker clear;
  clear.header.frame_id = frame_id;
  clear.header.stamp = stamp;
  clear.ns = kBrickMarkerNamespace;
  clear.action = Marker::DELETEALL;
  array.markers.push_back(clear);
  std::map<int, Marker> edges;
  for (const BrickSnapshot& brick : bricks) {
    if (!drawable(brick)) continue;
    appendBodyMarkers(brick, frame_id, stamp, &array);
    const int id = edgeMarkerId(brick);
    auto group = edges.find(id);
    if (group == edges.end()) group = edges.emplace(id, makeEdgeMarker(id, frame_id, stamp)).first;
    appendEdges(brick, &group->second.points);
  }
  for (auto& [id, marker] : edges) array.markers.push_back(std::move(marker));
  return array;
}

visualization_msgs::MarkerArray makeTableMarkers(const TableOptions& table,
                                                 const std::string& frame_id,
                                                 const ros::Time& stamp) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray array;
  const double length = table.size.x();
  const double width = table.size.y();
  for (double d : {length, width, table.thickness, table.height})
    if (!std::isfinite(d) || !(d > 0.0)) return array;

  auto box = [&](int id, const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
                 const std_msgs::ColorRGBA& color) {
    Marker marker = newMarker(frame_id, stamp, kTableMarkerNamespace, id, Marker::CUBE);
    marker.pose.position = toPointMsg(centre);
    marker.scale = toVectorMsg(size);
    marker.color = color;
    array.markers.push_back(marker);
  };
  // Light grey, so that pine and every tint stand out on it, and so that a
  // top seen at a grazing angle (RViz lights along the view) still stands
  // out from the background; the dark edges of the lowest layer show on it.
  const std_msgs::ColorRGBA top = rgb(0.80f, 0.80f, 0.82f);
  // The top is the box the world collides with (tableSolid()).
  box(0, tablePose(table).translation(), 2.0 * tableHalfExtents(table), top);
  // The floor, wider than the table by a table's width on every side: what
  // falls off lands there (fell-off bricks, red).
  constexpr double kFloorThickness = 0.01;  // [m]
  box(1, Eigen::Vector3d(0.0, 0.0, -table.height - 0.5 * kFloorThickness),
      Eigen::Vector3d(length + 2.0 * width, 3.0 * width, kFloorThickness),
      rgb(0.45f, 0.46f, 0.48f));
  const double leg = std::min(0.05, 0.1 * std::min(length, width));  // [m], square
  const double leg_height = table.height - table.thickness;
  if (leg_height > 0.0) {
    for (int i = 0; i < 4; ++i) {
      const double x = (i & 1 ? 1.0 : -1.0) * (0.5 * length - leg);
      const double y = (i & 2 ? 1.0 : -1.0) * (0.5 * width - leg);
      box(2 + i, Eigen::Vector3d(x, y, -table.thickness - 0.5 * leg_height),
          Eigen::Vector3d(leg, leg, leg_height), rgb(0.62f, 0.63f, 0.65f));
    }
  }
  return array;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
