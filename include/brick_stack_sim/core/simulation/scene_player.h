#pragma once

#include <cstddef>
#include <vector>

#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {

/// A placement of a scene that the world refused when its time came.
struct RefusedPlacement {
  double t = 0.0;  ///< Sim time of the attempt [s].
  std::string id;
  std::string reason;
};

/// Places a scene's bricks into a world when their time `at` comes, counted
/// from the sim time the player was started at. Shared by the batch runner and
/// the node, so a scene behaves the same in both.
class ScenePlayer {
 public:
  ScenePlayer() = default;
  /// Starts playing `bricks` (sorted by `at`) with time 0 = `start_time` [s].
  ScenePlayer(std::vector<ScheduledBrick> bricks, double start_time);

  /// Places every brick due at the world's current time; returns the refused ones.
  std::vector<RefusedPlacement> placeDue(BrickWorld* world);
  bool done() const { return next_ >= bricks_.size(); }
  std::size_t pending() const { return bricks_.size() - next_; }
  std::size_t scheduled() const { return bricks_.size(); }

 private:
  std::vector<ScheduledBrick> bricks_;
  double start_time_ = 0.0;
  std::size_t next_ = 0;
};

}  // namespace brick_stack_sim
