#pragma once

namespace brick_stack_sim {

struct WorldState;

/// After a Bullet step, for every awake mover: a brick Bullet drove to NaN,
/// Inf or a speed past the placement limits (a diverged solver, which ends
/// in NaN if left alone) is put back at its last good pose, at rest, and
/// reported as `nonfinite`; any other brick's pose becomes its last good
/// one, and a brick whose centre dropped below the table is reported as
/// `fell_off` once. No NaN or Inf ever leaves the world.
void guardMovers(WorldState* world);

}  // namespace brick_stack_sim
