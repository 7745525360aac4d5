#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/box_contact.h"
#include "brick_stack_sim/core/geometry/convex_polyhedron.h"

namespace brick_stack_sim {

/// One convex part of a solid.
struct ConvexPart {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< The part's frame in the solid's.
  ConvexPolyhedron polyhedron;                             ///< In the part's frame.
  /// Non-zero when the part is exactly the box of these half extents [m]
  /// centred on its frame: the box routines, exact and cheaper, judge it,
  /// so a box brick gives the same bits as before shapes existed.
  Eigen::Vector3d box_half_extents = Eigen::Vector3d::Zero();
  /// Radius and length [m] when the part stands for a cylinder along its
  /// frame's z (the polyhedron is its inscribed prism): drawn as one.
  double cylinder_radius = 0.0;
  double cylinder_length = 0.0;

  bool isBox() const { return box_half_extents.x() > 0.0; }
  bool isCylinder() const { return cylinder_radius > 0.0; }
};

/// A solid as the union of convex parts that do not overlap (one part for a
/// box, a cylinder or a hull; several for an arch block or an L).
struct ConvexSolid {
  std::vector<ConvexPart> parts;
};

/// A solid with exactly one part: the box of `half_extents` [m].
ConvexSolid boxSolid(const Eigen::Vector3d& half_extents);
/// A solid with exactly one part, `polyhedron`, in the solid's frame.
ConvexSolid polyhedronSolid(ConvexPolyhedron polyhedron);

/// A solid at a pose in the world; `solid` outlives it.
struct PlacedSolid {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const ConvexSolid* solid = nullptr;
};

/// The axis-aligned bounds of the placed solid [m].
Eigen::AlignedBox3d bounds(const PlacedSolid& placed);

/// Lowest and highest value of `axis . x` over the placed solid (unit `axis`) [m].
Eigen::Vector2d extentAlong(const PlacedSolid& placed, const Eigen::Vector3d& axis);

/// The least half width of the solid over all directions [m]: how far it
/// may move in a step before it could pass through something as thin.
double thinnestHalfWidth(const ConvexSolid& solid);

/// The largest distance [m] from `centre` (solid frame) to a vertex of the solid.
double radiusAbout(const ConvexSolid& solid, const Eigen::Vector3d& centre);

/// Separating-axis distance of two placed solids [m], as separation() of two
/// boxes: over every pair of parts, the largest gap along the parts' face
/// normals and the cross products of their edge directions; then the least
/// over the pairs. Positive: apart (a lower bound of the distance). Zero:
/// touching. Negative: some two parts overlap, this deep.
double separation(const PlacedSolid& a, const PlacedSolid& b);

/// The point of the placed solid (inside or on it) nearest `point` [m].
Eigen::Vector3d nearestPointIn(const PlacedSolid& placed, const Eigen::Vector3d& point);

/// The contacts of two placed solids that touch without overlapping, found
/// from geometry, as touchingContacts() of two boxes does it, over every
/// pair of parts: for each face whose plane separates the two parts within
/// `max_gap` [m], the other part's face turned most against it clipped to
/// that face, keeping the points within `max_gap` of the plane. A box on a
/// box gives exactly the box routine's answer. Normals from b towards a.
std::vector<BoxContactFace> touchingContacts(const PlacedSolid& a, const PlacedSolid& b,
                                             double max_gap);

/// The contact patch where a face of `upper` lies flush on a face of `lower`
/// (anti-parallel within `max_angle` [rad], within `max_gap` [m] of each
/// other's plane) and lower's face looks up (normal z > 0): their overlap,
/// on lower's face plane, over every pair of parts; `normal` (optional)
/// receives lower's face normal. Two boxes give exactly flushContactPatch()
/// of two boxes. False when no faces are flush.
bool flushContactPatch(const PlacedSolid& lower, const PlacedSolid& upper, double max_angle,
                       double max_gap, std::vector<Eigen::Vector3d>* patch,
                       Eigen::Vector3d* normal = nullptr);

}  // namespace brick_stack_sim
