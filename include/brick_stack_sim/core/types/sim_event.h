#pragma once

#include <string>
#include <vector>

namespace brick_stack_sim {

/// What happened to a brick (values match StabilityEvent.msg).
enum class SimEventKind : unsigned char {
  kSpawned = 0,
  kFrozen = 1,
  kWoken = 2,
  kImpact = 3,
  kFellOff = 4,
  kRemoved = 5,
  kNonFinite = 6,  ///< Bullet produced NaN, Inf or a runaway speed for this brick; it was restored.
  kGrasped = 7,    ///< Taken into a hand: kinematic, it follows the held target.
  kReleased = 8,   ///< Let go by the hand: simulated again.
  kLost = 9,       ///< Left the world box (WorldBounds): removed from the world.
};

/// Lower-case name used in reports: spawned, frozen, woken, impact, fell_off,
/// removed, nonfinite, grasped, released, lost.
const char* toString(SimEventKind kind);

struct SimEvent {
  double time = 0.0;  ///< Sim time [s].
  SimEventKind kind = SimEventKind::kSpawned;
  std::string brick_id;
  std::string reason;
  std::vector<std::string> affected;
};

}  // namespace brick_stack_sim
