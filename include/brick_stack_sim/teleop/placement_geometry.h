#pragma once
// Where a teleop puts a brick: ROS-free geometry on the bricks that
// ~get_bricks reports, so that it can be tested without a simulator.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/types/brick_type.h"

namespace brick_stack_sim {
namespace teleop {

/// Height of the table top in the world frame [m] (docs/ros_interface.md, "Frames and units").
constexpr double kTableTop = 0.0;

/// Least area [m^2] that two footprints must share for one brick to be under
/// the other: bricks lying side by side in a layer touch along an edge, and a
/// brick placed over that edge would otherwise land on the higher neighbour's
/// top while resting on nothing. A tenth of a millimetre squared is far below
/// any real support and far above rounding.
constexpr double kMinFootprintOverlap = 1e-8;

/// How far [m] a brick's size on the topic may be from its type's in the
/// teleop's library for the type's solid to stand for it: the same files
/// give the same bits; farther, the libraries differ and the box of the
/// brick's own size is the safer guess.
constexpr double kTypeSizeTolerance = 1e-6;

/// The solid a teleop judges a brick of `type` by, whose bounds' full
/// extents are `size` [m] (Brick.msg): its type's in `types` when known (and
/// of that size within kTypeSizeTolerance), else the box of `size`; null
/// when that is not finite and positive.
std::shared_ptr<const ConvexSolid> brickSolid(const BrickTypeLibrary& types,
                                              const std::string& type, const Eigen::Vector3d& size);

/// Solids at their poses together with the solids they point to: the
/// bricks a teleop read, valid as long as this lives.
struct SolidBricks {
  std::vector<PlacedSolid> placed;
  std::vector<std::shared_ptr<const ConvexSolid>> owners;  ///< placed[i].solid's owner.
  void add(const Eigen::Isometry3d& pose, std::shared_ptr<const ConvexSolid> solid);
};

/// Every number of the placed solid is finite, and it has a part.
bool finiteSolid(const PlacedSolid& placed);

/// The axis-aligned bounds of the placed solid [m], exact for box and
/// cylinder parts (Bullet moves the exact cylinder, not the prism that the
/// stability layer judges it by), the vertices' for a hull part.
Eigen::AlignedBox3d solidBounds(const PlacedSolid& placed);

/// The top [m] of what lies under `ghost`: the highest top of a part of
/// `bricks` whose footprint (its outline seen from above) overlaps a ghost
/// part's and whose top is not above the ghost's centre (its frame's
/// origin), or the table top when there is none. A part whose top is above
/// the ghost's centre is beside or over it, not under it; a brick with a
/// non-finite number is ignored. `ghost` must be finite.
double supportTopUnder(const PlacedSolid& ghost, const std::vector<PlacedSolid>& bricks);
/// The same for boxes: each the one-part solid of its box.
double supportTopUnder(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks);

/// The pose of `ghost` moved straight down (or up, when it sinks into what is
/// under it) until its lowest point lies on supportTopUnder(): where a brick
/// is put at rest. Orientation, x and y are kept.
Eigen::Isometry3d restingPose(const PlacedSolid& ghost, const std::vector<PlacedSolid>& bricks);
Eigen::Isometry3d restingPose(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks);

/// The lowest height [m] of the frame of `solid` turned by `rotation` whose
/// lowest point is still at or above the table top. A held brick's target
/// below it would put the brick into the table.
double lowestCentreZ(const ConvexSolid& solid, const Eigen::Matrix3d& rotation);
/// The same for a box of `half_extents` [m] centred on its frame: kTableTop
/// plus the box's half height along world z.
double lowestCentreZ(const Eigen::Vector3d& half_extents, const Eigen::Matrix3d& rotation);

/// Where the frame of a ghost `ghost` turned by `rotation` starts so that
/// it hides nothing: the ghost resting on the table top beside the +x side
/// of the bounding box, seen from above, of the finite `bricks` (the nearer
/// side in config/teleop.rviz's view), its own longest half side clear of
/// it, its bounds centred on the box's middle in y; `fallback` when there
/// is no such brick.
Eigen::Vector3d besideBricks(const std::vector<PlacedSolid>& bricks, const ConvexSolid& ghost,
                             const Eigen::Matrix3d& rotation, const Eigen::Vector3d& fallback);
/// The same for boxes, the ghost a box of `half_extents` (yaw 0).
Eigen::Vector3d besideBricks(const std::vector<OrientedBox>& bricks,
                             const Eigen::Vector3d& half_extents, const Eigen::Vector3d& fallback);

/// Index of the point of `centres` nearest to `point`; -1 when `centres` is
/// empty. Non-finite centres are never chosen.
int nearestIndex(const Eigen::Vector3d& point, const std::vector<Eigen::Vector3d>& centres);

}  // namespace teleop
}  // namespace brick_stack_sim
