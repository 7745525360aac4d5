#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/simulation/plan.h"
#include "brick_stack_sim/core/simulation/scene_player.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/sim_event.h"
#include "brick_stack_sim/core/types/world_options.h"
#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {

/// Sim time between the runner's looks for fallen bricks [s] (every step
/// when the step is longer): a fall's time is known to within it.
constexpr double kFallCheckInterval = 0.01;

/// How to run a scene without ROS.
struct RunOptions {
  WorldOptions world;              ///< Table is replaced by the scene's when it has one.
  std::optional<double> duration;  ///< Sim time [s]; default: last placement + 5 s.
  /// Called after every step and its placements (benchmarks sample with it).
  std::function<void(const BrickWorld&)> observer;
  /// A brick has fallen once its centre of mass is farther than this from
  /// where it was placed [m] (finite, > 0), or it fell off the table or was lost.
  double fall_distance = kDefaultFallDistance;
  /// Or once it has turned farther than this from how it was placed [rad] (finite, > 0).
  double fall_angle = kDefaultFallAngle;
  /// Judge the scene's first structure by statics before the run
  /// (RunReport::statics, judgeInitialStructure()).
  bool statics = false;
};

/// A brick's end state compared with where it was placed.
struct BrickOutcome {
  BrickSnapshot brick;
  double displacement = 0.0;      ///< |final - placed position| [m].
  double rotation = 0.0;          ///< Angle between final and placed orientation [rad].
  std::optional<double> fell_at;  ///< Sim time it was first seen fallen [s]; none: it has not.
};

/// A brick that fell, and when the runner first saw it fallen.
struct BrickFall {
  std::string id;
  double t = 0.0;  ///< Sim time [s]: a look's (within kFallCheckInterval), or a lost event's.
};

/// What rigid-block statics says of the structure a scene places at its
/// first instant (judgeInitialStructure()).
struct StaticsLabel {
  /// Contact forces within friction balance every brick of it, all free,
  /// on the table.
  bool stands = false;
  /// The least support margin of its bricks [m] (BrickSnapshot::margin: the
  /// COM of a brick and all it carries against the hull of what carries
  /// it); <= 0 when it does not stand, 0 with no bricks. Standing, it is
  /// <= 0 only where friction or a shared load holds a brick (a leaning one).
  double margin = 0.0;
  int bricks = 0;  ///< Bricks judged: those placed at the first instant (refused ones not).
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
  std::size_t scheduled = 0;   ///< Bricks the scene places within the duration.
  double fall_distance = 0.0;  ///< [m], as run.
  double fall_angle = 0.0;     ///< [rad], as run.
  /// Every brick that fell, lost ones included, in the order they were first
  /// seen fallen (by time; at one look, in placement order).
  std::vector<BrickFall> falls;
  std::optional<StaticsLabel> statics;  ///< Only when asked for (RunOptions::statics).

  /// Bricks that left the world box and were removed (each with a lost event).
  std::size_t lost() const { return cost.lost; }
  /// Placed bricks neither there at the end nor reported lost; anything but 0
  /// is a defect.
  std::size_t missing() const { return scheduled - refused.size() - bricks.size() - cost.lost; }

  double maxDisplacement() const;  ///< [m]; 0 with no bricks.
  /// Bricks there at the end that have not fallen.
  std::size_t standing() const;
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

/// A brick taken out of a scene, and why.
struct SetAsideBrick {
  ScheduledBrick brick;
  std::string reason;
};

/// Takes the bricks `bad` names (as findBadSceneBricks() lists them, in
/// index order) out of `scene`; returns them in scene order.
std::vector<SetAsideBrick> setAsideBadBricks(const std::vector<BadSceneBrick>& bad, Scene* scene);

/// Judges the structure `scene` places at its first instant (the bricks
/// whose `at` is the smallest), at rest where placed and together, by the
/// rigid-block statics of mode `equilibrium` with every brick free, on the
/// scene's table and with its friction, whatever `world`'s mode. Fails only
/// when the scene's table or types cannot make a world.
Status judgeInitialStructure(const Scene& scene, const BrickTypeLibrary& types,
                             const WorldOptions& world, StaticsLabel* label);

/// Runs `scene` for the requested duration, placing each brick at its time,
/// and watches for bricks that fall (every kFallCheckInterval and at the end).
Status runScene(const Scene& scene, const BrickTypeLibrary& types, const RunOptions& options,
                RunReport* report);

/// The report as JSON with the keys of docs/design.md, "The batch runner" (and a few more).
std::string toJson(const RunReport& report);

}  // namespace brick_stack_sim
