#include "brick_stack_sim/ros/stability_markers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "brick_stack_sim/ros/brick_markers.h"
#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

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

}  // namespace ros_adapter
}  // namespace brick_stack_sim
