#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick_shape.h"

namespace brick_stack_sim {

/// A kind of brick: a rigid solid of any convex shape or a compound of
/// convex parts. Geometry and inertia come from the URDF or the scene,
/// surface properties from the materials yaml. Poses everywhere are the
/// type frame's; the centre of mass sits at `mass_frame`.
struct BrickType {
  std::string name;
  BrickShape shape;  ///< As described; empty parts: a box of `size` (finishBrickType).
  /// Full extents x, y, z of the solid's bounds in the type frame [m]: a
  /// box's size.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  double mass = 0.0;                                  ///< [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  ///< Principal moments [kg m^2].
  /// The centre of mass and the principal axes of inertia in the type frame.
  Eigen::Isometry3d mass_frame = Eigen::Isometry3d::Identity();
  double friction = 0.5;          ///< Coulomb coefficient [-].
  double restitution = 0.0;       ///< [-], 0 = no bounce.
  double rolling_friction = 0.0;  ///< [m], Bullet's rolling friction.
  /// The solid the stability layer judges it by, in the type frame; shared
  /// by every brick of the type. Set by finishBrickType().
  std::shared_ptr<const ConvexSolid> solid;

  /// A box centred on its frame: the box routines and Bullet's box apply.
  bool isBox() const;
  /// Half the bounds' extents [m]: a box's half size.
  Eigen::Vector3d halfExtents() const { return 0.5 * size; }
  /// The solid at `pose`: valid while this type lives.
  PlacedSolid placed(const Eigen::Isometry3d& pose) const { return {pose, solid.get()}; }
  /// The largest distance of a point of the solid from the centre of mass [m].
  double reachFromCentreOfMass() const;
  /// How far it may move in a step before it could pass through something as thin [m].
  double thinnestHalfWidth() const;
};

/// Builds the type's solid from its shape (a box of `size` when the shape
/// has no parts), its `size` from the solid's bounds, and, unless
/// `inertia_given`, its inertia and mass frame from the solid at uniform
/// density; then validates it. The message names the type.
Status finishBrickType(BrickType* type, bool inertia_given);

/// The brick types known to a world, by name.
class BrickTypeLibrary {
 public:
  /// Reads every link with a collision (or visual) geometry and an inertial
  /// from `urdf_path` (a box, a cylinder, a mesh read as its convex hull;
  /// several collisions: a compound), then friction and restitution per type from the yaml at
  /// `materials_path` (keys `default` and `types: {name: {friction, restitution}}`).
  /// Either path may be a file; the yaml path may be empty (defaults apply).
  static Status load(const std::string& urdf_path, const std::string& materials_path,
                     BrickTypeLibrary* library);
  /// Same as load() but from strings, for tests and embedded descriptions;
  /// relative mesh file names are under `mesh_directory` (empty: the
  /// working directory).
  static Status parse(const std::string& urdf_xml, const std::string& materials_yaml,
                      BrickTypeLibrary* library, const std::string& mesh_directory = "");

  /// Adds or replaces a type after checking it is physical (positive,
  /// finite); a type without a solid is finished first (finishBrickType,
  /// inertia as given).
  Status add(BrickType type);
  const BrickType* find(const std::string& name) const;
  std::vector<std::string> names() const;
  bool empty() const { return types_.empty(); }

  /// The type used when a request names none: the materials yaml's
  /// `default_type`, else the alphabetically first type.
  const std::string& defaultType() const { return default_type_; }
  Status setDefaultType(const std::string& name);

 private:
  std::map<std::string, BrickType> types_;
  std::string default_type_;
};

/// Checks that every field of `type` is finite and physical.
Status validateBrickType(const BrickType& type);

}  // namespace brick_stack_sim
