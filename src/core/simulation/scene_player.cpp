#include "brick_stack_sim/core/simulation/scene_player.h"

#include <utility>

namespace brick_stack_sim {

ScenePlayer::ScenePlayer(std::vector<ScheduledBrick> bricks, double start_time)
    : bricks_(std::move(bricks)), start_time_(start_time) {}

std::vector<RefusedPlacement> ScenePlayer::placeDue(BrickWorld* world) {
  std::vector<RefusedPlacement> refused;
  // Half a step of slack: `at` = 1.0 s must not slip to the next step because
  // the step count times the step is 0.999999... s.
  const double now = world->time() + 0.5 * world->options().time_step;
  while (next_ < bricks_.size() && start_time_ + bricks_[next_].at <= now) {
    const ScheduledBrick& brick = bricks_[next_++];
    if (Status placed = world->addBrick(brick.placement); !placed)
      refused.push_back({world->time(), brick.placement.id, placed.message});
  }
  return refused;
}

}  // namespace brick_stack_sim
