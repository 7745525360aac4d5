#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/simulation/scene_player.h"
#include "brick_stack_sim/core/types/sim_event.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

/// How to run a scene without ROS.
struct RunOptions {
  WorldOptions world;              ///< Table is replaced by the scene's when it has one.
  std::optional<double> duration;  ///< Sim time [s]; default: last placement + 5 s.
  /// Called after every step and its placements (benchmarks sample with it).
  std::function<void(const BrickWorld&)> observer;
};

/// A brick's end state compared with where it was placed.
struct BrickOutcome {
  BrickSnapshot brick;
  double displacement = 0.0;  ///< |final - placed position| [m].
  double rotation = 0.0;      ///< Angle between final and placed orientation [rad].
};

struct RunReport {
  std::string scene;
  WorldOptions world;
  double sim_time = 0.0;
  double wall_time = 0.0;  ///< [s]
  CostCounters cost;
  std::vector<BrickOutcome> bricks;
  std::vector<SimEvent> events;
  std::vector<RefusedPlacement> refused;
  std::size_t scheduled = 0;  ///< Bricks the scene places within the duration.

  /// Bricks that left the world box and were removed (each with a lost event).
  std::size_t lost() const { return cost.lost; }
  /// Placed bricks neither there at the end nor reported lost; anything but 0
  /// is a defect.
  std::size_t missing() const { return scheduled - refused.size() - bricks.size() - cost.lost; }

  double maxDisplacement() const;  ///< [m]; 0 with no bricks.
};

/// A brick of a scene that can never be placed.
struct BadSceneBrick {
  std::size_t index = 0;  ///< In Scene::bricks.
  std::string reason;
};

/// The bricks of `scene` that would be refused whatever else the scene does:
/// each is checked as if placed alone on the scene's empty table (id, type,
/// pose, velocity, world box). Overlaps with other bricks depend on the run
/// and show in RunReport::refused instead. Fails only when the scene's
/// table or types cannot make a world.
Status findBadSceneBricks(const Scene& scene, const BrickTypeLibrary& types,
                          const WorldOptions& world, std::vector<BadSceneBrick>* bad);

/// Runs `scene` for the requested duration, placing each brick at its time.
Status runScene(const Scene& scene, const BrickTypeLibrary& types, const RunOptions& options,
                RunReport* report);

/// The report as JSON with the keys of docs/design.md, "The batch runner" (and a few more).
std::string toJson(const RunReport& report);

}  // namespace brick_stack_sim
