#include "brick_stack_sim/core/types/brick_shape.h"

#include <cmath>

#include "brick_stack_sim/core/geometry/box_geometry.h"

namespace brick_stack_sim {

namespace {

bool positiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

/// One part's solid and its own mass properties (in the part's frame).
struct PartBuild {
  ConvexPart part;
  ShapeMass mass;
};

Status buildBox(const ShapePart& described, PartBuild* built) {
  const Eigen::Vector3d& size = described.size;
  if (!positiveFinite(size.x()) || !positiveFinite(size.y()) || !positiveFinite(size.z()))
    return Status::error("box size must be positive and finite in x, y and z");
  const Eigen::Vector3d half = 0.5 * size;
  built->part.polyhedron = boxPolyhedron(half);
  built->part.box_half_extents = half;
  const Eigen::Vector3d squared = size.cwiseProduct(size);
  built->mass.volume = size.prod();
  built->mass.inertia = (Eigen::Vector3d(squared.y() + squared.z(), squared.x() + squared.z(),
                                         squared.x() + squared.y()) /
                         12.0)
                            .asDiagonal();
  return Status::success();
}

Status buildCylinder(const ShapePart& described, PartBuild* built) {
  const double r = described.radius, l = described.length;
  if (!positiveFinite(r) || !positiveFinite(l))
    return Status::error("cylinder radius and length must be positive and finite");
  built->part.polyhedron = cylinderPolyhedron(r, l, cylinderSides(r, kCylinderFacetSag));
  built->part.cylinder_radius = r;
  built->part.cylinder_length = l;
  // The exact cylinder's, not its prism's: Bullet moves the exact one.
  built->mass.volume = M_PI * r * r * l;
  const double across = (3.0 * r * r + l * l) / 12.0;
  built->mass.inertia = Eigen::Vector3d(across, across, 0.5 * r * r).asDiagonal();
  return Status::success();
}

Status buildConvex(const ShapePart& described, PartBuild* built) {
  if (Status hull = convexHull3d(described.vertices, &built->part.polyhedron); !hull)
    return Status::error("convex hull of its vertices: " + hull.message);
  const SolidMass solid = solidMass(built->part.polyhedron);
  if (!(solid.volume > 0.0)) return Status::error("convex hull of its vertices has no volume");
  built->mass.volume = solid.volume;
  built->mass.centroid = solid.centroid;
  built->mass.inertia = solid.inertia / solid.volume;
  return Status::success();
}

Status buildPart(const ShapePart& described, PartBuild* built) {
  if (!described.pose.matrix().allFinite() || !isRotation(described.pose.linear()))
    return Status::error("part pose must be finite with a proper rotation");
  built->part.pose = described.pose;
  switch (described.kind) {
    case ShapeKind::kBox:
      return buildBox(described, built);
    case ShapeKind::kCylinder:
      return buildCylinder(described, built);
    case ShapeKind::kConvex:
      return buildConvex(described, built);
    case ShapeKind::kCompound:
      break;
  }
  return Status::error("a compound part cannot itself be compound");
}

/// The parts' mass properties combined at one density, in the type frame
/// (parallel axes: the parts do not overlap).
ShapeMass combine(const std::vector<PartBuild>& parts) {
  ShapeMass total;
  for (const PartBuild& p : parts) {
    total.volume += p.mass.volume;
    total.centroid += p.mass.volume * (p.part.pose * p.mass.centroid);
  }
  total.centroid /= total.volume;
  Eigen::Matrix3d unit_density = Eigen::Matrix3d::Zero();
  for (const PartBuild& p : parts) {
    const Eigen::Matrix3d r = p.part.pose.linear();
    const Eigen::Vector3d d = p.part.pose * p.mass.centroid - total.centroid;
    unit_density +=
        p.mass.volume * (r * p.mass.inertia * r.transpose() +
                         (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
  }
  total.inertia = unit_density / total.volume;
  return total;
}

/// The bounds of one part as described, in the type frame: a cylinder's
/// exact ones, not its prism's.
void extendByPart(const ShapePart& part, const ConvexPart& solid, Eigen::AlignedBox3d* extent) {
  if (part.kind != ShapeKind::kCylinder) {
    for (const Eigen::Vector3d& v : solid.polyhedron.vertices) extent->extend(part.pose * v);
    return;
  }
  // Along a world axis e, a cylinder of axis a reaches l/2 |a.e| from its
  // centre by its axis and r sqrt(1 - (a.e)^2) by its rim.
  const Eigen::Vector3d axis = part.pose.linear().col(2);
  Eigen::Vector3d reach;
  for (int k = 0; k < 3; ++k)
    reach[k] = 0.5 * part.length * std::abs(axis[k]) +
               part.radius * std::sqrt(std::max(0.0, 1.0 - axis[k] * axis[k]));
  extent->extend(part.pose.translation() - reach);
  extent->extend(part.pose.translation() + reach);
}

}  // namespace

Eigen::AlignedBox3d shapeBounds(const BrickShape& shape, const ConvexSolid& solid) {
  Eigen::AlignedBox3d extent;
  for (std::size_t i = 0; i < shape.parts.size() && i < solid.parts.size(); ++i)
    extendByPart(shape.parts[i], solid.parts[i], &extent);
  return extent;
}

const char* toString(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::kBox:
      return "box";
    case ShapeKind::kCylinder:
      return "cylinder";
    case ShapeKind::kConvex:
      return "convex";
    case ShapeKind::kCompound:
      return "compound";
  }
  return "unknown";
}

BrickShape boxShape(const Eigen::Vector3d& size) {
  BrickShape shape;
  shape.kind = ShapeKind::kBox;
  shape.parts.resize(1);
  shape.parts[0].size = size;
  return shape;
}

BrickShape cylinderShape(double radius, double length) {
  BrickShape shape;
  shape.kind = ShapeKind::kCylinder;
  shape.parts.resize(1);
  shape.parts[0].kind = ShapeKind::kCylinder;
  shape.parts[0].radius = radius;
  shape.parts[0].length = length;
  return shape;
}

Status buildShape(const BrickShape& shape, ConvexSolid* solid, ShapeMass* mass) {
  if (shape.parts.empty()) return Status::error("a shape needs at least one part");
  if (shape.kind != ShapeKind::kCompound && shape.parts.size() != 1)
    return Status::error(std::string("a ") + toString(shape.kind) + " has exactly one part");
  std::vector<PartBuild> parts(shape.parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (shape.kind != ShapeKind::kCompound && shape.parts[i].kind != shape.kind)
      return Status::error("its part is not a " + std::string(toString(shape.kind)));
    if (Status built = buildPart(shape.parts[i], &parts[i]); !built)
      return shape.kind == ShapeKind::kCompound
                 ? Status::error("parts[" + std::to_string(i) + "]: " + built.message)
                 : built;
  }
  ConvexSolid result;
  for (const PartBuild& p : parts) result.parts.push_back(p.part);
  *mass = parts.size() == 1 && shape.parts[0].pose.matrix().isIdentity(0.0) ? parts[0].mass
                                                                            : combine(parts);
  *solid = std::move(result);
  return Status::success();
}

}  // namespace brick_stack_sim
