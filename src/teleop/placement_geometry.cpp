#include "brick_stack_sim/teleop/placement_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brick_stack_sim/core/geometry/polygon2d.h"

namespace brick_stack_sim {
namespace teleop {

namespace {

/// The part's frame in the world; an identity part pose keeps the solid's
/// pose bit for bit, so that a box brick lands where it did before shapes.
Eigen::Isometry3d partPose(const Eigen::Isometry3d& solid_pose, const ConvexPart& part) {
  return part.pose.matrix() == Eigen::Matrix4d::Identity() ? solid_pose : solid_pose * part.pose;
}

bool finitePart(const ConvexPart& part) {
  if (!part.pose.matrix().allFinite() || !part.box_half_extents.allFinite() ||
      !std::isfinite(part.cylinder_radius) || !std::isfinite(part.cylinder_length))
    return false;
  return std::all_of(part.polyhedron.vertices.begin(), part.polyhedron.vertices.end(),
                     [](const Eigen::Vector3d& v) { return v.allFinite(); });
}

Eigen::AlignedBox3d partBounds(const ConvexPart& part, const Eigen::Isometry3d& pose) {
  if (part.isBox()) return bounds(OrientedBox{pose, part.box_half_extents});
  Eigen::AlignedBox3d extent;
  if (part.isCylinder()) {
    // Along a world axis e, a cylinder of axis a reaches l/2 |a.e| from its
    // centre by its axis and r sqrt(1 - (a.e)^2) by its rim.
    const Eigen::Vector3d axis = pose.linear().col(2);
    Eigen::Vector3d reach;
    for (int k = 0; k < 3; ++k)
      reach[k] = 0.5 * part.cylinder_length * std::abs(axis[k]) +
                 part.cylinder_radius * std::sqrt(std::max(0.0, 1.0 - axis[k] * axis[k]));
    extent.extend(pose.translation() - reach);
    extent.extend(pose.translation() + reach);
    return extent;
  }
  for (const Eigen::Vector3d& v : part.polyhedron.vertices) extent.extend(pose * v);
  return extent;
}

/// The outline of a part seen from above [m]: the hull of its projected
/// corners or vertices, exact for a box and a hull since the projection of a
/// convex polyhedron is the hull of its projected vertices; a cylinder's is
/// its prism's, at most the prism's sag inside.
Polygon2d footprint(const ConvexPart& part, const Eigen::Isometry3d& pose) {
  std::vector<Eigen::Vector2d> points;
  if (part.isBox()) {
    for (const Eigen::Vector3d& corner : corners(OrientedBox{pose, part.box_half_extents}))
      points.push_back(corner.head<2>());
  } else {
    for (const Eigen::Vector3d& v : part.polyhedron.vertices)
      points.push_back((pose * v).head<2>());
  }
  return convexHull(points);
}

/// Each box as the one-part solid it stands for.
std::vector<ConvexSolid> boxSolids(const std::vector<OrientedBox>& boxes) {
  std::vector<ConvexSolid> solids;
  solids.reserve(boxes.size());
  for (const OrientedBox& box : boxes) solids.push_back(boxSolid(box.half_extents));
  return solids;
}

std::vector<PlacedSolid> placedBoxes(const std::vector<OrientedBox>& boxes,
                                     const std::vector<ConvexSolid>& solids) {
  std::vector<PlacedSolid> placed;
  for (std::size_t i = 0; i < boxes.size(); ++i) placed.push_back({boxes[i].pose, &solids[i]});
  return placed;
}

}  // namespace

std::shared_ptr<const ConvexSolid> brickSolid(const BrickTypeLibrary& types,
                                              const std::string& type,
                                              const Eigen::Vector3d& size) {
  const BrickType* known = types.find(type);
  if (known && known->solid && size.allFinite() &&
      (known->size - size).cwiseAbs().maxCoeff() <= kTypeSizeTolerance)
    return known->solid;
  if (!size.allFinite() || !(size.minCoeff() > 0.0)) return nullptr;
  return std::make_shared<const ConvexSolid>(boxSolid(0.5 * size));
}

void SolidBricks::add(const Eigen::Isometry3d& pose, std::shared_ptr<const ConvexSolid> solid) {
  placed.push_back({pose, solid.get()});
  owners.push_back(std::move(solid));
}

bool finiteSolid(const PlacedSolid& placed) {
  if (!placed.solid || placed.solid->parts.empty() || !placed.pose.matrix().allFinite())
    return false;
  return std::all_of(placed.solid->parts.begin(), placed.solid->parts.end(), finitePart);
}

Eigen::AlignedBox3d solidBounds(const PlacedSolid& placed) {
  Eigen::AlignedBox3d extent;
  for (const ConvexPart& part : placed.solid->parts)
    extent.extend(partBounds(part, partPose(placed.pose, part)));
  return extent;
}

double supportTopUnder(const PlacedSolid& ghost, const std::vector<PlacedSolid>& bricks) {
  std::vector<Polygon2d> ghost_footprints;
  for (const ConvexPart& part : ghost.solid->parts)
    ghost_footprints.push_back(footprint(part, partPose(ghost.pose, part)));
  const double ghost_centre_z = ghost.pose.translation().z();
  double top = kTableTop;
  for (const PlacedSolid& brick : bricks) {
    // The hull of a NaN corner is undefined: such a brick supports nothing.
    if (!finiteSolid(brick)) continue;
    for (const ConvexPart& part : brick.solid->parts) {
      const Eigen::Isometry3d pose = partPose(brick.pose, part);
      const double part_top = partBounds(part, pose).max().z();
      if (part_top <= top || part_top > ghost_centre_z) continue;
      const Polygon2d under = footprint(part, pose);
      if (std::any_of(ghost_footprints.begin(), ghost_footprints.end(), [&](const Polygon2d& f) {
            return area(intersectConvex(f, under)) >= kMinFootprintOverlap;
          }))
        top = part_top;
    }
  }
  return top;
}

double supportTopUnder(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks) {
  const ConvexSolid ghost_solid = boxSolid(ghost.half_extents);
  const std::vector<ConvexSolid> solids = boxSolids(bricks);
  return supportTopUnder(PlacedSolid{ghost.pose, &ghost_solid}, placedBoxes(bricks, solids));
}

Eigen::Isometry3d restingPose(const PlacedSolid& ghost, const std::vector<PlacedSolid>& bricks) {
  Eigen::Isometry3d pose = ghost.pose;
  pose.translation().z() += supportTopUnder(ghost, bricks) - solidBounds(ghost).min().z();
  return pose;
}

Eigen::Isometry3d restingPose(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks) {
  const ConvexSolid ghost_solid = boxSolid(ghost.half_extents);
  const std::vector<ConvexSolid> solids = boxSolids(bricks);
  return restingPose(PlacedSolid{ghost.pose, &ghost_solid}, placedBoxes(bricks, solids));
}

double lowestCentreZ(const ConvexSolid& solid, const Eigen::Matrix3d& rotation) {
  return kTableTop - solidBounds(PlacedSolid{Eigen::Isometry3d(rotation), &solid}).min().z();
}

double lowestCentreZ(const Eigen::Vector3d& half_extents, const Eigen::Matrix3d& rotation) {
  // The box's extent along world z: each of its axes' z component times its
  // half extent.
  return kTableTop + rotation.row(2).cwiseAbs().dot(half_extents.cwiseAbs());
}

Eigen::Vector3d besideBricks(const std::vector<PlacedSolid>& bricks, const ConvexSolid& ghost,
                             const Eigen::Matrix3d& rotation, const Eigen::Vector3d& fallback) {
  Eigen::AlignedBox3d around;
  for (const PlacedSolid& brick : bricks)
    if (finiteSolid(brick)) around.extend(solidBounds(brick));
  const PlacedSolid turned{Eigen::Isometry3d(rotation), &ghost};
  if (around.isEmpty() || !finiteSolid(turned)) return fallback;
  // The ghost's bounds about its own frame, as turned.
  const Eigen::AlignedBox3d own = solidBounds(turned);
  const double longest_half = 0.5 * own.sizes().maxCoeff();
  return Eigen::Vector3d(around.max().x() - own.min().x() + longest_half,
                         0.5 * (around.min().y() + around.max().y()) - own.center().y(),
                         kTableTop - own.min().z());
}

Eigen::Vector3d besideBricks(const std::vector<OrientedBox>& bricks,
                             const Eigen::Vector3d& half_extents, const Eigen::Vector3d& fallback) {
  const std::vector<ConvexSolid> solids = boxSolids(bricks);
  return besideBricks(placedBoxes(bricks, solids), boxSolid(half_extents.cwiseAbs()),
                      Eigen::Matrix3d::Identity(), fallback);
}

int nearestIndex(const Eigen::Vector3d& point, const std::vector<Eigen::Vector3d>& centres) {
  int nearest = -1;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const double distance = (centres[i] - point).squaredNorm();
    if (distance < nearest_distance) {
      nearest_distance = distance;
      nearest = static_cast<int>(i);
    }
  }
  return nearest;
}

}  // namespace teleop
}  // namespace brick_stack_sim
