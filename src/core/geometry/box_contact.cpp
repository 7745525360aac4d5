#include "brick_stack_sim/core/geometry/box_contact.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/polygon_clip.h"

namespace brick_stack_sim {

namespace {

/// Parallel within this [-] (1 - cos of about 1.4 mrad): faces seen from
/// both sides are one contact.
constexpr double kSameDirection = 1.0 - 1e-6;
/// Points closer than this many gaps are one [-].
constexpr double kSamePoint = 10.0;

/// The face of `box` turned most against `direction`, as a polygon.
std::vector<Eigen::Vector3d> faceAgainst(const OrientedBox& box, const Eigen::Vector3d& direction) {
  const Eigen::Matrix3d& r = box.pose.linear();
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(r.col(i).dot(direction)) > std::abs(r.col(axis).dot(direction))) axis = i;
  const double sign = r.col(axis).dot(direction) <= 0.0 ? 1.0 : -1.0;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Eigen::Vector3d centre =
      box.pose.translation() + sign * r.col(axis) * box.half_extents[axis];
  const Eigen::Vector3d du = r.col(u) * box.half_extents[u], dv = r.col(v) * box.half_extents[v];
  return {centre - du - dv, centre + du - dv, centre + du + dv, centre - du + dv};
}

/// The contacts across the faces of `reference` on which `incident` rests;
/// `towards_a` is +1 when `reference` is box b (normals point out of it).
void contactsOnFaces(const OrientedBox& reference, const OrientedBox& incident, double towards_a,
                     double max_gap, std::vector<BoxContactFace>* faces) {
  const Eigen::Matrix3d& r = reference.pose.linear();
  const std::array<Eigen::Vector3d, 8> incident_corners = corners(incident);
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      const Eigen::Vector3d n = sign * r.col(axis);
      const Eigen::Vector3d on_face =
          reference.pose.translation() + n * reference.half_extents[axis];
      double nearest = n.dot(incident_corners[0] - on_face);
      for (const Eigen::Vector3d& corner : incident_corners)
        nearest = std::min(nearest, n.dot(corner - on_face));
      // The face's plane must separate the boxes, touching within the gap.
      if (std::abs(nearest) > max_gap) continue;
      const Eigen::Vector3d normal = towards_a * n;
      const bool seen = std::any_of(faces->begin(), faces->end(), [&](const BoxContactFace& f) {
        return f.normal.dot(normal) > kSameDirection;
      });
      if (seen) continue;
      std::vector<Eigen::Vector3d> polygon = faceAgainst(incident, n);
      for (int side = 1; side <= 2 && !polygon.empty(); ++side) {
        const int k = (axis + side) % 3;
        const double limit = reference.half_extents[k] + max_gap;
        polygon = clipPolygon(polygon, r.col(k), reference.pose.translation(), limit);
        if (!polygon.empty())
          polygon = clipPolygon(polygon, -r.col(k), reference.pose.translation(), limit);
      }
      BoxContactFace face;
      face.normal = normal;
      for (const Eigen::Vector3d& p : polygon) {
        const double depth = n.dot(p - on_face);
        if (depth > max_gap) continue;
        // Clipping within the gap splits a corner on the face's rim in two.
        const Eigen::Vector3d on_plane = p - depth * n;
        const bool duplicate =
            std::any_of(face.points.begin(), face.points.end(), [&](const Eigen::Vector3d& q) {
              return (q - on_plane).norm() <= kSamePoint * std::max(max_gap, 1e-9);
            });
        if (!duplicate) face.points.push_back(on_plane);
      }
      if (!face.points.empty()) faces->push_back(std::move(face));
    }
  }
}

}  // namespace

std::vector<BoxContactFace> touchingContacts(const OrientedBox& a, const OrientedBox& b,
                                             double max_gap) {
  std::vector<BoxContactFace> faces;
  contactsOnFaces(b, a, 1.0, max_gap, &faces);
  contactsOnFaces(a, b, -1.0, max_gap, &faces);
  return faces;
}

}  // namespace brick_stack_sim
