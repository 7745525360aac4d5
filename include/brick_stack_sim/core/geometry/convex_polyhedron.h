#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// A bounded convex polyhedron in its own frame: the geometry every brick
/// shape is judged by (a cylinder as an inscribed prism, a mesh as its hull).
struct ConvexPolyhedron {
  struct Face {
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, outward.
    double offset = 0.0;    ///< normal . x = offset on the face's plane [m].
    std::vector<int> loop;  ///< Vertex indices, counter-clockwise seen from outside.
  };
  std::vector<Eigen::Vector3d> vertices;  ///< [m]
  std::vector<Face> faces;                ///< Coplanar facets merged: one face per plane.
  std::vector<std::array<int, 2>> edges;  ///< Each edge once (vertex indices).
};

/// The box of `half_extents` [m] centred on the origin, axes along x, y, z.
ConvexPolyhedron boxPolyhedron(const Eigen::Vector3d& half_extents);

/// The right prism of `sides` sides inscribed in the cylinder of `radius`
/// and `length` [m], centred on the origin, axis along z: its vertices lie
/// on the cylinder, its side faces at most radius (1 - cos(pi / sides))
/// inside it.
ConvexPolyhedron cylinderPolyhedron(double radius, double length, int sides);

/// The fewest sides (even, at least 16) whose inscribed prism lies within
/// `max_sag` [m] of a cylinder of `radius` [m].
int cylinderSides(double radius, double max_sag);

/// The convex hull of `points` [m], coplanar facets merged into one face and
/// points inside or on a face dropped. An error (saying why) when the points
/// span no volume: fewer than 4 of them, all on one plane or line, or not
/// finite.
Status convexHull3d(const std::vector<Eigen::Vector3d>& points, ConvexPolyhedron* hull);

/// Volume [m^3], centroid [m] and inertia tensor about the centroid, axes of
/// the polyhedron's frame, of the solid at unit density [m^5] (times a
/// density [kg/m^3]: kg m^2).
struct SolidMass {
  double volume = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// The mass properties of the solid `polyhedron` bounds (exact for a
/// polyhedron, by the divergence theorem over its faces' triangles).
SolidMass solidMass(const ConvexPolyhedron& polyhedron);

}  // namespace brick_stack_sim
