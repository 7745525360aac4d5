#pragma once

#include <optional>
#include <string>
#include <vector>

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

/// A brick of a scene and the sim time at which it is placed.
struct ScheduledBrick {
  BrickPlacement placement;
  double at = 0.0;  ///< Placement time [s].
};

/// What a scene's author expects of the structure it builds; a planner
/// client (blueprint_builder) fails a build that does otherwise. Bricks
/// placed with a velocity (thrown) are not part of the structure.
enum class ExpectedOutcome {
  kStands,     ///< Every brick comes to rest where it was placed and stays.
  kCollapses,  ///< Some brick falls: a demonstration of a stability limit.
};

/// A scene (docs/design.md, "Simulation and scenes"): an optional table
/// override, optional extra brick types, and bricks with placement times,
/// sorted by `at` (stable). `generator` may be one generator or a list of them.
struct Scene {
  std::string name;
  std::optional<TableOptions> table;
  std::vector<BrickType> types;
  std::vector<ScheduledBrick> bricks;
  ExpectedOutcome expect = ExpectedOutcome::kStands;  ///< YAML `expect: stands | collapses`.
};

/// Latest placement time a scene may give [s]: 11.6 days of sim time, more
/// than any run reaches; a larger `at` is a typo that would make a runner
/// simulate until killed.
constexpr double kMaxSceneTime = 1e6;

/// Default of the largest scene file loadScene() reads [bytes]: 64 MiB.
constexpr int kDefaultSceneMaxBytes = 64 << 20;
/// Default of the most bricks a scene may hold, its generators' and its
/// `bricks` list together: as many as one tower or pile may place.
constexpr int kDefaultSceneMaxBricks = 100000;

/// What a scene may cost before it is read or built (docs/ros_interface.md,
/// "Refusals and limits").
struct SceneLimits {
  int max_bytes = kDefaultSceneMaxBytes;    ///< Largest scene file read [bytes].
  int max_bricks = kDefaultSceneMaxBricks;  ///< Most bricks of one scene.
};

/// Parses a scene from YAML text. `types` resolves the generators' brick sizes
/// (together with the scene's own types); `name` is used when the yaml has none.
/// What each generator would place is counted from its parameters before any
/// brick is built: a scene over `limits.max_bricks` is refused, naming the
/// generator (counted from 1) at which the total passes it.
Status parseScene(const std::string& yaml_text, const std::string& name,
                  const BrickTypeLibrary& types, Scene* scene, const SceneLimits& limits = {});

/// Loads a scene from a file, or by name from `scene_dirs` (`<dir>/<name>.yaml`).
/// Only a regular file (after links) is read, once
/// and without blocking: a FIFO, a device such as /dev/zero, a directory or
/// a file over `limits.max_bytes` is refused at once with a message that
/// says which; its bricks are counted as parseScene() does.
Status loadScene(const std::string& name_or_path, const std::vector<std::string>& scene_dirs,
                 const BrickTypeLibrary& types, Scene* scene, const SceneLimits& limits = {});

/// Adds the scene's own types to `types` (the scene's win on a name clash).
Status mergeSceneTypes(const Scene& scene, BrickTypeLibrary* types);

/// A scene of `types` alone and no bricks, as YAML that parseScene() reads
/// back into the same shapes, masses and materials (inertia from the solid):
/// how a client hands a simulator the types a scene defines.
std::string typesAsScene(const std::vector<BrickType>& types);

}  // namespace brick_stack_sim
