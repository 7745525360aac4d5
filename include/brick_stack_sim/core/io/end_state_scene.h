#pragma once
// The state a run ended in, as a scene to run again from there.

#include <vector>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/scene/scene.h"

namespace brick_stack_sim {

/// A brick of a run's end that a scene cannot place.
struct LeftOutBrick {
  std::string id;
  std::string reason;  ///< Why a scene cannot place it (below the table top, ...).
};

/// The scene `report` ended in, run from `scene`: the same name, expected
/// outcome, table, friction and types, and every brick there at the end,
/// placed at t = 0 where it was, with the velocities it had. The bricks no
/// scene can place (fallen to the floor, which lies below the table top) are
/// left out into `left_out`, in report order, with the reason. `types` and
/// `world` are those of the run. Fails only when the scene's table or types
/// cannot make a world.
Status endStateScene(const Scene& scene, const RunReport& report, const BrickTypeLibrary& types,
                     const WorldOptions& world, Scene* end_state,
                     std::vector<LeftOutBrick>* left_out);

}  // namespace brick_stack_sim
