#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/convex_solid.h"

namespace brick_stack_sim {

/// How the simulator currently treats a brick (values match Brick.msg).
enum class BrickState : unsigned char {
  kDynamic = 0,  ///< Simulated by Bullet.
  kStable = 1,   ///< Frozen: rests stably in the stack.
  kLeaning = 2,  ///< Frozen: held by the leaning (friction) model.
  kHeld = 3,     ///< Moved kinematically by a teleop or planner.
};

/// Lower-case name used in reports: dynamic, stable, leaning, held.
const char* toString(BrickState state);

/// A request to put a brick into the world.
struct BrickPlacement {
  std::string id;                                          ///< Empty: the world names it brick_<n>.
  std::string type;                                        ///< Empty: the library's default type.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< Centre of the brick, frame world.
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();   ///< [m/s], frame world.
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< [rad/s], frame world.
};

/// Everything known about one brick at one instant.
struct BrickSnapshot {
  std::string id;
  std::string type;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();   ///< [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< [rad/s]
  Eigen::Vector3d size = Eigen::Vector3d::Zero();              ///< Bounds' full extents [m].
  /// Its type's solid in the brick's frame (shared, never changed): what
  /// markers draw. Null: a box of `size`.
  std::shared_ptr<const ConvexSolid> solid;
  double mass = 0.0;  ///< [kg]
  BrickState state = BrickState::kDynamic;
  bool asleep = false;    ///< Bullet has deactivated it (mode none with sleeping).
  bool fell_off = false;  ///< It has dropped below the table top.
  Eigen::Vector3d com_above = Eigen::Vector3d::Zero();  ///< COM of it and all it carries [m].
  double mass_above = 0.0;                              ///< [kg], including itself.
  std::vector<std::string> supported_by;                ///< Brick ids, or "table".
  double margin = 0.0;  ///< Signed distance [m] of the COM-above projection to the support
                        ///< hull edge (< 0: outside). 0 when nothing supports the brick, or
                        ///< no stability model measures it.
  Eigen::Isometry3d placed_pose = Eigen::Isometry3d::Identity();
  double placed_at = 0.0;  ///< Sim time of placement [s].
  unsigned serial = 0;     ///< Order of placement since the last reset, from 0; never reused.
};

/// Where a brick rests, for markers: each support patch and the combined hull
/// as polygons in the world (counter-clockwise seen from above) [m].
struct SupportGeometry {
  struct Patch {
    std::string supporter;  ///< Brick id, "table" or "floor".
    std::vector<Eigen::Vector3d> polygon;
  };
  /// A force the brick receives at one contact, as the statics LP found it.
  struct ContactForce {
    std::string other;                                  ///< Brick id, "table" or "floor".
    Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< [m]
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, from `other` into the brick.
    Eigen::Vector3d force = Eigen::Vector3d::Zero();    ///< On the brick [N], world gravity.
    double friction = 0.0;                              ///< Coulomb coefficient [-].
  };
  std::vector<Patch> patches;
  std::vector<Eigen::Vector3d> combined_hull;  ///< At the mean support height.
  Eigen::Vector3d com_above = Eigen::Vector3d::Zero();
  double margin = 0.0;  ///< [m], < 0: the COM-above projection is outside.
  /// Where statics was solved for it (a frozen leaning brick and what it
  /// leans with; in mode equilibrium, any brick of a component whose LP
  /// ran): one set of contact forces that balances it. Empty otherwise.
  std::vector<ContactForce> contact_forces;
};

}  // namespace brick_stack_sim
