#include "brick_stack_sim/ros/brick_markers.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "brick_stack_sim/core/geometry/box_geometry.h"
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

}  // namespace

void appendEdges(const BrickSnapshot& brick, std::vector<geometry_msgs::Point>* lines) {
  if (!drawable(brick)) return;
  const std::array<Eigen::Vector3d, 8> corner = corners(
      OrientedBox{brick.pose, 0.5 * brick.size + Eigen::Vector3d::Constant(kBrickEdgeInflation)});
  // Corner i's bits say which side of each axis it lies on (corners()), so
  // the corners i and i + bit differ along one axis: every edge once.
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) appendSegment(corner[i], corner[i | bit], lines);
}

void appendBoxMarker(const BrickSnapshot& brick, const std::string& frame_id,
                     const ros::Time& stamp, visualization_msgs::MarkerArray* array) {
  using visualization_msgs::Marker;
  if (!drawable(brick)) return;
  Marker box =
      newMarker(frame_id, stamp, kBrickMarkerNamespace, brickMarkerId(brick), Marker::CUBE);
  box.pose = toPoseMsg(brick.pose);
  box.scale = toVectorMsg(brick.size);
  box.color = brickColor(brick);
  array->markers.push_back(std::move(box));
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
    appendBoxMarker(brick, frame_id, stamp, &array);
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
  box(0, Eigen::Vector3d(0.0, 0.0, -0.5 * table.thickness),
      Eigen::Vector3d(length, width, table.thickness), top);
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
