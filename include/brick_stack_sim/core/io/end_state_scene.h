#pragma once
// The state a run ended in, as a scene to run again from there.

#include <vector>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/scene/scene.h"

namespace brick_stack_sim {

/// The scene `report` ended in, run from `scene`: the same name, expected
/// outcome, table, friction and types, and every brick there at the end,
/// placed at t = 0 where it was, with the velocities it had. The bricks no
/// scene can place (fallen to the floor, which lies below the table top) are
/// left out into `left_out`, in report order, each with the reason. `types` and
/// `world` are those of the run. Fails only when the scene's table or types
/// cannot make a world.
Status endStateScene(const Scene& scene, const RunReport& report, const BrickTypeLibrary& types,
                     const WorldOptions& world, Scene* end_state,
                     std::vector<SetAsideBrick>* left_out);

}  // namespace brick_stack_sim
