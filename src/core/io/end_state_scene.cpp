// The state a run ended in, as a scene (end_state_scene.h).
#include "brick_stack_sim/core/io/end_state_scene.h"

namespace brick_stack_sim {

Status endStateScene(const Scene& scene, const RunReport& report, const BrickTypeLibrary& types,
                     const WorldOptions& world, Scene* end_state,
                     std::vector<SetAsideBrick>* left_out) {
  Scene state;
  state.name = scene.name;
  state.table = scene.table;
  state.types = scene.types;
  state.expect = scene.expect;
  state.friction = scene.friction;
  for (const BrickOutcome& outcome : report.bricks) {
    const BrickSnapshot& brick = outcome.brick;
    ScheduledBrick placed;
    placed.placement.id = brick.id;
    placed.placement.type = brick.type;
    placed.placement.pose = brick.pose;
    placed.placement.linear_velocity = brick.linear_velocity;
    placed.placement.angular_velocity = brick.angular_velocity;
    state.bricks.push_back(std::move(placed));
  }
  std::vector<BadSceneBrick> bad;
  if (Status checked = findBadSceneBricks(state, types, world, &bad); !checked) return checked;
  *left_out = setAsideBadBricks(bad, &state);
  *end_state = std::move(state);
  return Status::success();
}

}  // namespace brick_stack_sim
