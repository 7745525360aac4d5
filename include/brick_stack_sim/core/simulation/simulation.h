#pragma once

#include <memory>
#include <vector>

#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/simulation/scene_player.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/types/sim_event.h"
#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {

/// A scene's world built apart from the simulation that will play it
/// (Simulation::prepareReset), ready to be swapped in at once
/// (Simulation::applyReset).
struct PreparedReset {
  std::unique_ptr<BrickWorld> world;  ///< With the scene's bricks due at its start placed.
  ScenePlayer player;                 ///< The scene's later bricks.
  std::vector<RefusedPlacement> refused;
};

/// A world, the scene it plays and a clock that never goes backwards: what
/// the batch runner and the node's ~reset share, so that a scene behaves
/// the same in both.
class Simulation {
 public:
  /// An empty table at time 0, with `options` and the configured `types`.
  static Status create(const WorldOptions& options, const BrickTypeLibrary& types,
                       std::unique_ptr<Simulation>* simulation);

  /// Replaces every brick by the scene's (an empty Scene: an empty table). The
  /// scene plays in a new world, with its own table and types when it brings
  /// them, whose clock goes on from now; the old bricks are reported removed
  /// ("scene reset") and the bricks due now are placed at once. On failure
  /// (the scene's table or types are invalid) nothing changes.
  Status reset(const Scene& scene);
  /// The expensive half of reset(): builds the scene's world with its clock
  /// at `start_time` [s] and places the bricks due then. Reads only what
  /// never changes after create(), so it may run while another thread uses
  /// the simulation, as long as the simulation's time stays `start_time`
  /// until applyReset() (the clock must not go backwards). On failure
  /// `*prepared` is left empty and nothing changes.
  Status prepareReset(const Scene& scene, double start_time, PreparedReset* prepared) const;
  /// The quick half: reports the current bricks removed ("scene reset") and
  /// swaps the prepared world in. Returns the replaced world, so that the
  /// caller can let it go where its destruction (every Bullet body) holds up
  /// nobody.
  std::unique_ptr<BrickWorld> applyReset(PreparedReset prepared);
  /// One world step, then the scene's placements that have come due.
  void step();

  double time() const { return world_->time(); }  ///< Sim time [s].
  BrickWorld& world() { return *world_; }
  const BrickWorld& world() const { return *world_; }
  const ScenePlayer& player() const { return player_; }
  const WorldOptions& options() const { return options_; }
  /// The configured types: what a scene's own types are added to.
  const BrickTypeLibrary& types() const { return types_; }

  /// Events since the last call, oldest first (those of replaced worlds first).
  std::vector<SimEvent> takeEvents();
  /// Placements of the scene the world refused since the last call.
  std::vector<RefusedPlacement> takeRefused();

 private:
  Simulation(const WorldOptions& options, const BrickTypeLibrary& types);

  WorldOptions options_;
  BrickTypeLibrary types_;  ///< The configured types; a scene adds its own to a copy.
  std::unique_ptr<BrickWorld> world_;
  ScenePlayer player_;
  std::vector<SimEvent> events_;  ///< Of worlds already replaced.
  std::vector<RefusedPlacement> refused_;
};

}  // namespace brick_stack_sim
