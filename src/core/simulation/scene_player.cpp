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
  // Bricks due at one instant are placed together: a structure placed at
  // once is judged as a whole (BrickWorld::addBricks).
  std::vector<BrickPlacement> due;
  std::vector<std::string> ids;
  while (next_ < bricks_.size() && start_time_ + bricks_[next_].at <= now) {
    due.push_back(bricks_[next_].placement);
    ids.push_back(bricks_[next_++].placement.id);
  }
  if (due.empty()) return refused;
  const std::vector<Status> placed = world->addBricks(due);
  for (std::size_t i = 0; i < placed.size(); ++i)
    if (!placed[i]) refused.push_back({world->time(), ids[i], placed[i].message});
  return refused;
}

}  // namespace brick_stack_sim
