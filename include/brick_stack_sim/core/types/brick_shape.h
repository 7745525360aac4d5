#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// What a brick's solid is, as a scene or a URDF describes it.
enum class ShapeKind : unsigned char {
  kBox,       ///< A cuboid: `size`.
  kCylinder,  ///< A circular cylinder: `radius`, `length`, axis along the part's z.
  kConvex,    ///< The convex hull of `vertices` (a URDF mesh is read as one).
  kCompound,  ///< Convex parts, each with a pose in the type frame.
};

/// Lower-case name used in scenes and messages: box, cylinder, convex, compound.
const char* toString(ShapeKind kind);

/// One convex piece of a solid as described.
struct ShapePart {
  ShapeKind kind = ShapeKind::kBox;                ///< kBox, kCylinder or kConvex.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  ///< Box: full extents [m].
  double radius = 0.0;                             ///< Cylinder [m].
  double length = 0.0;                             ///< Cylinder, along its z [m].
  std::vector<Eigen::Vector3d> vertices;           ///< Convex: the points it is the hull of [m].
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< In the type frame.
};

/// A brick's solid as described: one part, or several for kCompound.
struct BrickShape {
  ShapeKind kind = ShapeKind::kBox;
  std::vector<ShapePart> parts;
};

/// A box of full extents `size` [m] centred on the type frame.
BrickShape boxShape(const Eigen::Vector3d& size);
/// A cylinder [m] centred on the type frame, axis along z.
BrickShape cylinderShape(double radius, double length);

/// A cylinder is simulated and judged as the inscribed prism whose faces
/// lie at most this far inside it [m]: a fifth of the contact distance,
/// finer than a turned wooden cylinder is round; 70 sides at 20 mm radius.
/// Every check of a pair costs with the square of the sides.
constexpr double kCylinderFacetSag = 2e-5;

/// Mass properties of a shape at uniform density.
struct ShapeMass {
  double volume = 0.0;                                 ///< [m^3]
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< Type frame [m].
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   ///< About the centroid, per kg [m^2].
};

/// Checks the shape's geometry (sizes positive and finite, a hull with
/// volume, a compound with parts and none of them compound) and builds the
/// solid the stability layer judges it by and its mass properties.
/// Messages say what is wrong, not whose: the caller names the type.
Status buildShape(const BrickShape& shape, ConvexSolid* solid, ShapeMass* mass);

/// The bounds of the shape as described, in the type frame [m] (a
/// cylinder's exact ones, not its prism's); `solid` is buildShape()'s.
Eigen::AlignedBox3d shapeBounds(const BrickShape& shape, const ConvexSolid& solid);

}  // namespace brick_stack_sim
