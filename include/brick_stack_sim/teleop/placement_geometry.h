#pragma once
// Where a teleop puts a brick: ROS-free geometry on the bricks that
// ~get_bricks reports, so that it can be tested without a simulator.

#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/box_geometry.h"

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

/// The top [m] of what lies under `ghost`: the highest top among `bricks`
/// whose footprint (their outline seen from above) overlaps the ghost's and
/// whose top is not above the ghost's centre, or the table top when there is
/// none. A brick whose top is above the ghost's centre is beside or over it,
/// not under it; a brick with a non-finite pose or size is ignored. `ghost`
/// must be finite.
double supportTopUnder(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks);

/// The pose of `ghost` moved straight down (or up, when it sinks into what is
/// under it) until its lowest corner lies on supportTopUnder(): where a brick
/// is put at rest. Orientation, x and y are kept.
Eigen::Isometry3d restingPose(const OrientedBox& ghost, const std::vector<OrientedBox>& bricks);

/// The lowest height [m] of the centre of a box of `half_extents` [m] turned
/// by `rotation` whose lowest corner is still at or above the table top:
/// kTableTop plus the box's half height along world z. A held brick's target
/// below it would put the brick into the table.
double lowestCentreZ(const Eigen::Vector3d& half_extents, const Eigen::Matrix3d& rotation);

/// Where a ghost of `half_extents` (yaw 0) starts so that it hides nothing:
/// resting on the table top beside the +x side of the bounding box, seen from
/// above, of the finite `bricks` (the nearer side in config/teleop.rviz's
/// view), its own longest half side clear of it, and at the box's middle in
/// y; `fallback` when there is no such brick.
Eigen::Vector3d besideBricks(const std::vector<OrientedBox>& bricks,
                             const Eigen::Vector3d& half_extents, const Eigen::Vector3d& fallback);

/// Index of the point of `centres` nearest to `point`; -1 when `centres` is
/// empty. Non-finite centres are never chosen.
int nearestIndex(const Eigen::Vector3d& point, const std::vector<Eigen::Vector3d>& centres);

}  // namespace teleop
}  // namespace brick_stack_sim
