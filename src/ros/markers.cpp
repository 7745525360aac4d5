#include "brick_stack_sim/ros/markers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

std_msgs::ColorRGBA rgb(float r, float g, float b, float a = 1.0f) {
  std_msgs::ColorRGBA color;
  color.r = r;
  color.g = g;
  color.b = b;
  color.a = a;
  return color;
}

std_msgs::ColorRGBA opaque(std_msgs::ColorRGBA color) {
  color.a = 1.0f;  // text: a translucent legend would be harder to read
  return color;
}

// The colours of the stability layer, shared with the legend.
std_msgs::ColorRGBA contactPointColor() { return rgb(1.00f, 1.00f, 1.00f); }        // white
std_msgs::ColorRGBA forceArrowColor() { return rgb(0.95f, 0.10f, 0.85f); }          // magenta
std_msgs::ColorRGBA frictionConeColor() { return rgb(0.10f, 0.85f, 0.95f, 0.3f); }  // cyan
std_msgs::ColorRGBA patchColor() { return rgb(0.10f, 0.55f, 1.00f, 0.90f); }        // blue
std_msgs::ColorRGBA hullColor() { return rgb(1.00f, 0.85f, 0.10f, 0.35f); }  // translucent yellow

/// A marker with everything but its geometry: header, namespace, id, ADD, and
/// an identity pose (RViz warns about the all-zero quaternion of a default one).
visualization_msgs::Marker newMarker(const std::string& frame_id, const ros::Time& stamp,
                                     const char* ns, int id, int type) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id;
  marker.header.stamp = stamp;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.frame_locked = false;
  return marker;
}

bool allFinite(const std::vector<Eigen::Vector3d>& polygon) {
  for (const Eigen::Vector3d& vertex : polygon)
    if (!vertex.allFinite()) return false;
  return true;
}

/// Appends the fan triangulation of a convex polygon (counter-clockwise from
/// above, so every triangle faces up), lifted by `lift` [m]. A fan of a convex
/// polygon covers it exactly, without overlap. Nothing for fewer than three
/// vertices or a non-finite one.
void appendFan(const std::vector<Eigen::Vector3d>& polygon, double lift,
               std::vector<geometry_msgs::Point>* triangles) {
  if (polygon.size() < 3 || !allFinite(polygon)) return;
  const Eigen::Vector3d up(0.0, 0.0, lift);
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    triangles->push_back(toPointMsg(polygon[0] + up));
    triangles->push_back(toPointMsg(polygon[i] + up));
    triangles->push_back(toPointMsg(polygon[i + 1] + up));
  }
}

/// The height the COM-above ray ends at [m]: the combined hull's (the mean
/// support height), else the mean of the patches' vertices; false when the
/// brick rests on nothing.
bool supportHeight(const SupportGeometry& geometry, double* height) {
  if (!geometry.combined_hull.empty()) {
    *height = geometry.combined_hull.front().z();
    return std::isfinite(*height);
  }
  double sum = 0.0;
  std::size_t count = 0;
  for (const SupportGeometry::Patch& patch : geometry.patches) {
    for (const Eigen::Vector3d& vertex : patch.polygon) {
      sum += vertex.z();
      ++count;
    }
  }
  if (count == 0) return false;
  *height = sum / static_cast<double>(count);
  return std::isfinite(*height);
}

/// A friction cone is drawn as this many generators and a rim of
/// kConeRimSegments: enough to read as a cone, few enough not to hide the arrow.
constexpr int kConeGenerators = 4;
constexpr int kConeRimSegments = 16;
/// Forces shorter than this fraction of the brick's weight arrow are only points.
constexpr double kLeastDrawnForce = 1e-3;

bool finite(const SupportGeometry::ContactForce& f) {
  return f.point.allFinite() && f.normal.allFinite() && f.force.allFinite() &&
         std::isfinite(f.friction);
}

/// Any unit vector perpendicular to `direction` (unit).
Eigen::Vector3d perpendicular(const Eigen::Vector3d& direction) {
  const Eigen::Vector3d axis =
      std::abs(direction.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  return direction.cross(axis).normalized();
}

void appendSegment(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                   std::vector<geometry_msgs::Point>* lines) {
  lines->push_back(toPointMsg(from));
  lines->push_back(toPointMsg(to));
}

/// A shaft from `tail` to `tip` and a two-barbed head at `tip`.
void appendArrow(const Eigen::Vector3d& tail, const Eigen::Vector3d& tip,
                 std::vector<geometry_msgs::Point>* lines) {
  const Eigen::Vector3d along = tip - tail;
  const double length = along.norm();
  const Eigen::Vector3d direction = along / length;
  const double head = std::min(0.25 * length, 0.005);
  const Eigen::Vector3d side = 0.5 * head * perpendicular(direction);
  appendSegment(tail, tip, lines);
  appendSegment(tip, tip - head * direction + side, lines);
  appendSegment(tip, tip - head * direction - side, lines);
}

/// The cone's generators from `apex`, then its rim, `height` along `axis`.
void appendCone(const Eigen::Vector3d& apex, const Eigen::Vector3d& axis, double height,
                double friction, std::vector<geometry_msgs::Point>* lines) {
  const Eigen::Vector3d u = perpendicular(axis);
  const Eigen::Vector3d v = axis.cross(u);
  auto rim = [&](double angle) {
    return Eigen::Vector3d(
        apex + height * (axis + friction * (std::cos(angle) * u + std::sin(angle) * v)));
  };
  for (int k = 0; k < kConeGenerators; ++k)
    appendSegment(apex, rim(2.0 * M_PI * k / kConeGenerators), lines);
  for (int k = 0; k < kConeRimSegments; ++k)
    appendSegment(rim(2.0 * M_PI * k / kConeRimSegments),
                  rim(2.0 * M_PI * (k + 1) / kConeRimSegments), lines);
}

/// One force per patch (the points a brick has with one body along one
/// normal): their sum, at their centre of pressure (the points weighted by
/// their normal parts; their mean when nothing presses). Four arrows and
/// cones at the corners of one face say no more than one, and hide it.
std::vector<SupportGeometry::ContactForce> patchResultants(
    const std::vector<SupportGeometry::ContactForce>& forces) {
  constexpr double kSameNormal = 1e-6;
  struct Sum {
    SupportGeometry::ContactForce resultant;
    Eigen::Vector3d pressed_point = Eigen::Vector3d::Zero();
    double pressure = 0.0;
    Eigen::Vector3d point_sum = Eigen::Vector3d::Zero();
    int count = 0;
  };
  std::vector<Sum> sums;
  for (const SupportGeometry::ContactForce& f : forces) {
    if (!finite(f) || f.normal.norm() < 0.5) continue;
    const Eigen::Vector3d normal = f.normal.normalized();
    auto same = std::find_if(sums.begin(), sums.end(), [&](const Sum& sum) {
      return sum.resultant.other == f.other && (sum.resultant.normal - normal).norm() < kSameNormal;
    });
    if (same == sums.end()) {
      sums.emplace_back();
      same = std::prev(sums.end());
      same->resultant = f;
      same->resultant.normal = normal;
      same->resultant.force.setZero();
    }
    const double pressure = std::max(0.0, f.force.dot(normal));
    same->resultant.force += f.force;
    same->pressed_point += pressure * f.point;
    same->pressure += pressure;
    same->point_sum += f.point;
    ++same->count;
  }
  std::vector<SupportGeometry::ContactForce> resultants;
  for (Sum& sum : sums) {
    sum.resultant.point = sum.pressure > 0.0 ? Eigen::Vector3d(sum.pressed_point / sum.pressure)
                                             : Eigen::Vector3d(sum.point_sum / sum.count);
    resultants.push_back(sum.resultant);
  }
  return resultants;
}

/// The kLeaningMarkerNamespace markers of one brick (none without forces).
void appendContactForces(const BrickSnapshot& brick, const SupportGeometry& geometry,
                         const std::string& frame_id, const ros::Time& stamp,
                         visualization_msgs::MarkerArray* array) {
  using visualization_msgs::Marker;
  const double scale = forceArrowScale(brick);
  if (geometry.contact_forces.empty() || !(scale > 0.0)) return;
  Marker points = newMarker(frame_id, stamp, kLeaningMarkerNamespace, contactPointsMarkerId(brick),
                            Marker::SPHERE_LIST);
  Marker arrows = newMarker(frame_id, stamp, kLeaningMarkerNamespace, forceArrowsMarkerId(brick),
                            Marker::LINE_LIST);
  Marker cones = newMarker(frame_id, stamp, kLeaningMarkerNamespace, frictionConesMarkerId(brick),
                           Marker::LINE_LIST);
  const double least = kLeastDrawnForce * kWeightArrowFraction * brick.size.maxCoeff();
  for (const SupportGeometry::ContactForce& f : geometry.contact_forces)
    if (finite(f) && f.normal.norm() >= 0.5) points.points.push_back(toPointMsg(f.point));
  for (const SupportGeometry::ContactForce& f : patchResultants(geometry.contact_forces)) {
    const Eigen::Vector3d arrow = scale * f.force;
    if (arrow.norm() < least) continue;
    appendArrow(f.point - arrow, f.point, &arrows.points);
    const double height = arrow.dot(f.normal);
    if (f.friction > 0.0 && height >= least)
      appendCone(f.point, -f.normal, height, f.friction, &cones.points);
  }
  points.scale.x = points.scale.y = points.scale.z = kContactPointSize;
  arrows.scale.x = kForceLineWidth;  // LINE_LIST: only x, the line width
  cones.scale.x = kFrictionConeLineWidth;
  points.color = contactPointColor();
  arrows.color = forceArrowColor();
  cones.color = frictionConeColor();
  for (Marker* marker : {&points, &arrows, &cones})
    if (!marker->points.empty()) array->markers.push_back(std::move(*marker));
}

}  // namespace

BrickLook brickLook(const BrickSnapshot& brick) {
  if (brick.fell_off) return BrickLook::kFellOff;
  switch (brick.state) {
    case BrickState::kHeld:
      return BrickLook::kHeld;
    case BrickState::kLeaning:
      return BrickLook::kLeaning;
    case BrickState::kStable:
      return BrickLook::kStable;
    case BrickState::kDynamic:
      break;
  }
  return brick.asleep ? BrickLook::kAsleep : BrickLook::kDynamic;
}

const char* lookName(BrickLook look) {
  switch (look) {
    case BrickLook::kFellOff:
      return "fell off";
    case BrickLook::kHeld:
      return "held";
    case BrickLook::kLeaning:
      return "leaning";
    case BrickLook::kStable:
      return "stable";
    case BrickLook::kAsleep:
      return "asleep";
    case BrickLook::kDynamic:
      return "dynamic";
  }
  return "?";
}

std_msgs::ColorRGBA brickColor(BrickLook look) {
  // Stable is the common case and the calm one: the plank's own pine. The
  // others are tints a viewer names at once, each at least 0.25 from every
  // other in RGB, far more than the wood tone's spread, and no channel so
  // bright that the tone's lighter half would clip (test_markers checks).
  switch (look) {
    case BrickLook::kFellOff:
      return rgb(0.86f, 0.22f, 0.18f);  // red
    case BrickLook::kHeld:
      return rgb(0.72f, 0.42f, 0.90f);  // violet
    case BrickLook::kLeaning:
      return rgb(0.90f, 0.52f, 0.10f);  // amber
    case BrickLook::kStable:
      return rgb(0.87f, 0.71f, 0.47f);  // pine
    case BrickLook::kAsleep:
      return rgb(0.52f, 0.52f, 0.54f);  // slate grey
    case BrickLook::kDynamic:
      return rgb(0.58f, 0.70f, 0.88f);  // blue-grey
  }
  return rgb(1.0f, 1.0f, 1.0f);
}

std_msgs::ColorRGBA brickColor(const BrickSnapshot& brick) {
  // The fractional parts of n times the golden ratio spread evenly over [0, 1)
  // and consecutive ones are 0.382 or 0.618 apart: the tones of neighbours
  // never coincide, and nothing random makes two runs look different.
  constexpr double kGoldenRatioFraction = 0.6180339887498949;
  const double unit = std::fmod(kGoldenRatioFraction * static_cast<double>(brick.serial), 1.0);
  const float factor = static_cast<float>(1.0 + kWoodToneSpread * (2.0 * unit - 1.0));
  std_msgs::ColorRGBA color = brickColor(brickLook(brick));
  color.r = std::min(1.0f, color.r * factor);
  color.g = std::min(1.0f, color.g * factor);
  color.b = std::min(1.0f, color.b * factor);
  return color;
}

int brickMarkerId(const BrickSnapshot& brick) { return static_cast<int>(brick.serial); }

int patchMarkerId(const BrickSnapshot& brick) { return 2 * static_cast<int>(brick.serial); }
int hullMarkerId(const BrickSnapshot& brick) { return 2 * static_cast<int>(brick.serial) + 1; }

int contactPointsMarkerId(const BrickSnapshot& brick) { return 3 * static_cast<int>(brick.serial); }
int forceArrowsMarkerId(const BrickSnapshot& brick) {
  return 3 * static_cast<int>(brick.serial) + 1;
}
int frictionConesMarkerId(const BrickSnapshot& brick) {
  return 3 * static_cast<int>(brick.serial) + 2;
}

double forceArrowScale(const BrickSnapshot& brick) {
  constexpr double kGravity = 9.81;  // [m/s^2]: a scale, not physics
  const double weight = brick.mass * kGravity;
  const double length = brick.size.allFinite() ? brick.size.maxCoeff() : 0.0;
  if (!(weight > 0.0) || !std::isfinite(weight) || !(length > 0.0)) return 0.0;
  return kWeightArrowFraction * length / weight;
}

std_msgs::ColorRGBA comAboveColor(double margin) {
  // Brighter than the box colours, so a ray inside a green stable brick stands out.
  return margin > 0.0 ? rgb(0.20f, 1.00f, 0.20f) : rgb(1.00f, 0.10f, 0.10f);
}

int edgeMarkerId(const BrickSnapshot& brick) {
  return static_cast<int>(brick.serial / kBricksPerEdgeMarker);
}

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

std::vector<LegendEntry> legendEntries() {
  // Short lines: the legend stands beside the bricks in the default view,
  // where a long line would reach over them.
  std::vector<LegendEntry> entries;
  entries.push_back({"brick colour = state", rgb(0.95f, 0.95f, 0.95f)});
  for (BrickLook look : kAllBrickLooks) {
    const char* meaning = "";
    switch (look) {
      case BrickLook::kStable:
        meaning = "frozen, resting";
        break;
      case BrickLook::kLeaning:
        meaning = "frozen, by friction";
        break;
      case BrickLook::kDynamic:
        meaning = "moving (Bullet)";
        break;
      case BrickLook::kAsleep:
        meaning = "Bullet sleeps it";
        break;
      case BrickLook::kHeld:
        meaning = "teleop or planner";
        break;
      case BrickLook::kFellOff:
        meaning = "off the table";
        break;
    }
    entries.push_back({std::string(lookName(look)) + ": " + meaning, brickColor(look)});
  }
  entries.push_back({"ray: COM-above to support", comAboveColor(1.0)});
  entries.push_back({"red ray: COM-above outside", comAboveColor(-1.0)});
  entries.push_back({"blue: contacts, yellow: hull", opaque(patchColor())});
  entries.push_back({"arrows: force, 1/3 plank = weight", forceArrowColor()});
  entries.push_back({"cyan: friction cones", opaque(frictionConeColor())});
  entries.push_back({"untick 'bricks' to see inside", rgb(0.75f, 0.75f, 0.75f)});
  return entries;
}

visualization_msgs::MarkerArray makeLegendMarkers(const TableOptions& table,
                                                  const std::string& frame_id,
                                                  const ros::Time& stamp) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray array;
  if (!table.size.allFinite() || !(table.size.minCoeff() > 0.0)) return array;
  // Over the table, back right of the default view (config/demo.rviz looks
  // along +y, slightly toward -x): beside a tower or a card house at the
  // centre, in front of nothing. A small table pulls it in to its corner.
  const double x = std::min(kLegendOffsetX, 0.5 * table.size.x());
  const double y = std::min(kLegendOffsetY, 0.5 * table.size.y());
  const std::vector<LegendEntry> entries = legendEntries();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    Marker line = newMarker(frame_id, stamp, kLegendMarkerNamespace, static_cast<int>(i),
                            Marker::TEXT_VIEW_FACING);
    line.pose.position.x = x;
    line.pose.position.y = y;
    line.pose.position.z = kLegendTop - static_cast<double>(i) * kLegendLineSpacing;
    line.scale.z = kLegendTextHeight;  // TEXT_VIEW_FACING: only z, the height of a capital
    line.text = entries[i].text;
    line.color = entries[i].color;
    array.markers.push_back(line);
  }
  return array;
}

void appendStabilityMarkers(const BrickSnapshot& brick, const SupportGeometry& geometry,
                            const std::string& frame_id, const ros::Time& stamp,
                            visualization_msgs::MarkerArray* array) {
  using visualization_msgs::Marker;
  double height = 0.0;
  if (geometry.com_above.allFinite() && std::isfinite(geometry.margin) &&
      supportHeight(geometry, &height)) {
    Marker ray = newMarker(frame_id, stamp, kComAboveMarkerNamespace, brickMarkerId(brick),
                           Marker::LINE_LIST);
    const Eigen::Vector3d top = geometry.com_above;
    const Eigen::Vector3d foot(top.x(), top.y(), height);
    const double arm = kComAboveFootSize;
    for (const Eigen::Vector3d& point :
         {top, foot, Eigen::Vector3d(foot + Eigen::Vector3d(-arm, 0, 0)),
          Eigen::Vector3d(foot + Eigen::Vector3d(arm, 0, 0)),
          Eigen::Vector3d(foot + Eigen::Vector3d(0, -arm, 0)),
          Eigen::Vector3d(foot + Eigen::Vector3d(0, arm, 0))})
      ray.points.push_back(toPointMsg(point));
    ray.scale.x = kComAboveLineWidth;  // LINE_LIST: only x, the line width
    ray.color = comAboveColor(geometry.margin);
    array->markers.push_back(ray);
  }

  Marker patches = newMarker(frame_id, stamp, kContactMeshMarkerNamespace, patchMarkerId(brick),
                             Marker::TRIANGLE_LIST);
  for (const SupportGeometry::Patch& patch : geometry.patches)
    appendFan(patch.polygon, kContactMeshLift, &patches.points);
  // The hull sits just under the patches so that they show through it.
  Marker hull = newMarker(frame_id, stamp, kContactMeshMarkerNamespace, hullMarkerId(brick),
                          Marker::TRIANGLE_LIST);
  appendFan(geometry.combined_hull, 0.5 * kContactMeshLift, &hull.points);
  patches.scale.x = patches.scale.y = patches.scale.z = 1.0;  // TRIANGLE_LIST: a factor
  hull.scale = patches.scale;
  patches.color = patchColor();
  hull.color = hullColor();
  // Empty lists are left out (RViz flags a TRIANGLE_LIST without points as
  // an error); a brick that loses them has them deleted (MarkerUpdates), or
  // the DELETEALL at the head of a full array removes them.
  if (!patches.points.empty()) array->markers.push_back(patches);
  if (!hull.points.empty()) array->markers.push_back(hull);
  appendContactForces(brick, geometry, frame_id, stamp, array);
}

visualization_msgs::MarkerArray makeStabilityMarkers(const std::vector<BrickSnapshot>& bricks,
                                                     const SupportGeometryMap& supports,
                                                     const std::string& frame_id,
                                                     const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  for (const BrickSnapshot& brick : bricks) {
    const auto found = supports.find(brick.id);
    if (found != supports.end())
      appendStabilityMarkers(brick, found->second, frame_id, stamp, &array);
  }
  return array;
}

visualization_msgs::MarkerArray makeMarkers(const std::vector<BrickSnapshot>& bricks,
                                            const SupportGeometryMap& supports,
                                            const TableOptions& table, const std::string& frame_id,
                                            const ros::Time& stamp) {
  visualization_msgs::MarkerArray array = makeBrickMarkers(bricks, frame_id, stamp);
  for (const visualization_msgs::MarkerArray& part :
       {makeTableMarkers(table, frame_id, stamp), makeLegendMarkers(table, frame_id, stamp),
        makeStabilityMarkers(bricks, supports, frame_id, stamp)})
    array.markers.insert(array.markers.end(), part.markers.begin(), part.markers.end());
  return array;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
