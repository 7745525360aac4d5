#include "brick_stack_sim/core/types/brick_type.h"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "types/inertial.h"

namespace brick_stack_sim {

namespace {

bool positiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

/// A box of `size` centred on the type frame, as every type was before
/// shapes: its inertia keeps the closed form's bits.
bool isCentredBox(const BrickShape& shape) {
  // Compared whole rather than by isIdentity(): the stability stage asks this
  // of every mover each step, and Eigen's element loop was most of the cost.
  return shape.kind == ShapeKind::kBox && shape.parts.size() == 1 &&
         shape.parts[0].pose.matrix() == Eigen::Matrix4d::Identity();
}

/// Principal moments and axes (a proper rotation) of a symmetric tensor; a
/// diagonal one keeps its axes and its bits.
void principalAxes(const Eigen::Matrix3d& tensor, Eigen::Vector3d* moments, Eigen::Matrix3d* axes) {
  if (Eigen::Matrix3d(tensor.diagonal().asDiagonal()) == tensor) {
    *moments = tensor.diagonal();
    axes->setIdentity();
    return;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(tensor);
  *moments = solver.eigenvalues();
  *axes = solver.eigenvectors();
  if (axes->determinant() < 0.0) axes->col(2) = -axes->col(2);
}

}  // namespace

bool BrickType::isBox() const { return isCentredBox(shape); }

double BrickType::reachFromCentreOfMass() const {
  if (isBox() || !solid) return halfExtents().norm();
  return radiusAbout(*solid, mass_frame.translation());
}

double BrickType::thinnestHalfWidth() const {
  if (isBox() || !solid) return halfExtents().minCoeff();
  return brick_stack_sim::thinnestHalfWidth(*solid);
}

Status finishBrickType(BrickType* type, bool inertia_given) {
  const std::string name = "brick type '" + type->name + "'";
  if (type->shape.parts.empty()) type->shape = boxShape(type->size);
  auto solid = std::make_shared<ConvexSolid>();
  ShapeMass shape_mass;
  if (Status built = buildShape(type->shape, solid.get(), &shape_mass); !built)
    return Status::error(name + ": " + built.message);
  if (!isCentredBox(type->shape)) {
    type->size = shapeBounds(type->shape, *solid).sizes();
  } else {
    type->size = type->shape.parts[0].size;
  }
  if (!inertia_given) {
    if (isCentredBox(type->shape)) {
      // A uniform box: m/12 (b^2 + c^2) about each axis.
      const Eigen::Vector3d squared = type->size.cwiseProduct(type->size);
      type->inertia = type->mass / 12.0 *
                      Eigen::Vector3d(squared.y() + squared.z(), squared.x() + squared.z(),
                                      squared.x() + squared.y());
      type->mass_frame.setIdentity();
    } else {
      Eigen::Matrix3d axes;
      principalAxes(type->mass * shape_mass.inertia, &type->inertia, &axes);
      type->mass_frame.linear() = axes;
      type->mass_frame.translation() = shape_mass.centroid;
    }
  }
  type->solid = std::move(solid);
  return validateBrickType(*type);
}

Status inertialFrame(const Eigen::Isometry3d& origin, const Eigen::Matrix3d& tensor,
                     Eigen::Vector3d* moments, Eigen::Isometry3d* mass_frame) {
  if (!tensor.allFinite() || !origin.matrix().allFinite())
    return Status::error("inertia and its origin must be finite");
  Eigen::Matrix3d axes;
  principalAxes(tensor, moments, &axes);
  *mass_frame = origin;
  mass_frame->linear() = origin.linear() * axes;
  return Status::success();
}

Status validateBrickType(const BrickType& t) {
  const std::string name = "brick type '" + t.name + "'";
  if (t.name.empty()) return Status::error("brick type without a name");
  if (!positiveFinite(t.size.x()) || !positiveFinite(t.size.y()) || !positiveFinite(t.size.z()))
    return Status::error(name + ": size must be positive and finite in x, y and z");
  if (!positiveFinite(t.mass)) return Status::error(name + ": mass must be positive and finite");
  if (!t.mass_frame.matrix().allFinite() || !isRotation(t.mass_frame.linear()))
    return Status::error(name + ": centre of mass and principal axes must be finite");
  const Eigen::Vector3d& i = t.inertia;
  if (!positiveFinite(i.x()) || !positiveFinite(i.y()) || !positiveFinite(i.z()))
    return Status::error(name + ": principal inertia must be positive and finite");
  // A real body's principal moments obey the triangle inequality; a violation
  // means a typo in the URDF, which would make Bullet spin the brick.
  const double slack = 1e-9 * i.sum();
  if (i.x() > i.y() + i.z() + slack || i.y() > i.x() + i.z() + slack ||
      i.z() > i.x() + i.y() + slack)
    return Status::error(name + ": principal inertia violates the triangle inequality");
  if (!std::isfinite(t.friction) || t.friction < 0.0)
    return Status::error(name + ": friction must be >= 0");
  if (!std::isfinite(t.restitution) || t.restitution < 0.0 || t.restitution > 1.0)
    return Status::error(name + ": restitution must be in [0, 1]");
  if (!std::isfinite(t.rolling_friction) || t.rolling_friction < 0.0)
    return Status::error(name + ": rolling_friction must be >= 0");
  return Status::success();
}

Status BrickTypeLibrary::add(BrickType type) {
  if (!type.solid) {
    if (Status finished = finishBrickType(&type, true); !finished) return finished;
  }
  if (Status valid = validateBrickType(type); !valid) return valid;
  const std::string name = type.name;
  types_[name] = std::move(type);
  if (default_type_.empty()) default_type_ = types_.begin()->first;
  return Status::success();
}

const BrickType* BrickTypeLibrary::find(const std::string& name) const {
  auto it = types_.find(name);
  return it == types_.end() ? nullptr : &it->second;
}

std::vector<std::string> BrickTypeLibrary::names() const {
  std::vector<std::string> result;
  for (const auto& entry : types_) result.push_back(entry.first);
  return result;
}

Status BrickTypeLibrary::setDefaultType(const std::string& name) {
  if (!find(name)) return Status::error("default brick type '" + name + "' is not a known type");
  default_type_ = name;
  return Status::success();
}

}  // namespace brick_stack_sim
