#pragma once

namespace brick_stack_sim {

struct WorldState;

/// Stage 1, before Bullet's step: each held brick moves toward its target,
/// no faster than the held speed limits. What it would strike on the way is
/// judged as an impact by a striker that does not give way: a blow that
/// moves a frozen brick wakes or slides it; a gentle one (and the table, the
/// floor) stops the hand there, so a held brick never passes through
/// anything. A frozen brick that stops it short of its target is pressed
/// as by a spring to the target (HeldOptions::stiffness), as contacts in
/// the world's presses. Bullet derives the held brick's velocity from the
/// move and pushes the moving bricks it touches.
void moveHeldBricks(WorldState* world);

}  // namespace brick_stack_sim
