#pragma once

#include <cstdint>
#include <limits>

namespace brick_stack_sim {

/// Names a body for the stability models and the Bullet scene: a brick's
/// placement serial, or one of the two static bodies. Models never see Bullet.
using BodyHandle = std::uint32_t;
constexpr BodyHandle kTableHandle = std::numeric_limits<BodyHandle>::max();
constexpr BodyHandle kFloorHandle = kTableHandle - 1;
inline bool isGround(BodyHandle handle) { return handle >= kFloorHandle; }

}  // namespace brick_stack_sim
