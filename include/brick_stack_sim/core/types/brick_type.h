#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// A kind of brick: a uniform box. Geometry and inertia come from the URDF,
/// surface properties from the materials yaml.
struct BrickType {
  std::string name;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();     ///< Full extents x, y, z [m].
  double mass = 0.0;                                  ///< [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  ///< Principal moments [kg m^2].
  double friction = 0.5;                              ///< Coulomb coefficient [-].
  double restitution = 0.0;                           ///< [-], 0 = no bounce.
  double rolling_friction = 0.0;                      ///< [m], Bullet's rolling friction.

  Eigen::Vector3d halfExtents() const { return 0.5 * size; }
};

/// The brick types known to a world, by name.
class BrickTypeLibrary {
 public:
  /// Reads every link with a box collision (or visual) geometry and an inertial
  /// from `urdf_path`, then friction and restitution per type from the yaml at
  /// `materials_path` (keys `default` and `types: {name: {friction, restitution}}`).
  /// Either path may be a file; the yaml path may be empty (defaults apply).
  static Status load(const std::string& urdf_path, const std::string& materials_path,
                     BrickTypeLibrary* library);
  /// Same as load() but from strings, for tests and embedded descriptions.
  static Status parse(const std::string& urdf_xml, const std::string& materials_yaml,
                      BrickTypeLibrary* library);

  /// Adds or replaces a type after checking it is physical (positive, finite).
  Status add(const BrickType& type);
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
