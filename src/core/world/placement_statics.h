#pragma once

#include <string>
#include <vector>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/types/brick.h"
#include "physics/contact.h"

namespace brick_stack_sim {

struct WorldState;

/// What statics says of one brick at rest, everything it touches held fixed.
struct StaticsVerdict {
  bool stands = false;
  BrickState kind = BrickState::kDynamic;  ///< kStable, or kLeaning when its COM is not over
                                           ///< what carries it from below.
  double margin = 0.0;                     ///< COM against the hull of its supports from below [m].
  double acceleration_margin =
      0.0;  ///< Least sideways acceleration (+-x, +-y) that moves it [m/s^2].
  std::vector<BodyHandle> touching;  ///< In handle order.
  std::string reason;
};

/// The contacts of a brick at `box` with everything it touches: the table
/// and bricks in any mode (mode none has no frozen bricks), across every
/// touching face.
std::vector<PairContact> touchingBricks(const WorldState& world, BodyHandle brick, double friction,
                                        const PlacedSolid& box, const Eigen::Vector3d& low,
                                        const Eigen::Vector3d& high);

/// Rigid-block statics of `brick` alone on `contacts` (all with a = brick).
StaticsVerdict judgeAlone(const BodyMotion& brick, const std::vector<PairContact>& contacts,
                          const WorldState& world);

}  // namespace brick_stack_sim
