#pragma once

#include <cstdint>
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

/// A scene's `pose_noise`: each brick's x and y offset by independent
/// uniform draws in [-position, position] and its orientation turned about
/// world z by a uniform draw in [-yaw, yaw], in the order of Scene::bricks,
/// from std::mt19937_64 seeded with `seed` (docs/design.md, "Simulation and
/// scenes").
struct PoseNoise {
  double position = 0.0;   ///< Bound of each horizontal offset [m], in [0, kMaxPoseNoise].
  double yaw = 0.0;        ///< Bound of the turn about world z [rad], in [0, pi].
  std::uint64_t seed = 0;  ///< Of the generator of the draws.
};

/// Largest `pose_noise.position` [m]: more is no longer noise on a structure
/// of bricks a few centimetres wide, but a typo.
constexpr double kMaxPoseNoise = 0.1;

/// A scene (docs/design.md, "Simulation and scenes"): an optional table
/// override, optional extra brick types, and bricks with placement times,
/// sorted by `at` (stable). `generator` may be one generator or a list of them.
struct Scene {
  std::string name;
  std::optional<TableOptions> table;
  std::vector<BrickType> types;
  std::vector<ScheduledBrick> bricks;
  ExpectedOutcome expect = ExpectedOutcome::kStands;  ///< YAML `expect: stands | collapses`.
  /// YAML `friction`: the Coulomb coefficient [-] of every brick type and of
  /// the table (and floor) in this scene, so that every contact has it
  /// (Bullet's geometric mean of two equal coefficients is that coefficient).
  /// Applied by mergeSceneTypes() and sceneWorldOptions().
  std::optional<double> friction;
  /// YAML `pose_noise`, as read; parseScene() has already applied it to `bricks`.
  std::optional<PoseNoise> pose_noise;
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

/// Adds the scene's own types to `types` (the scene's win on a name clash);
/// with the scene's `friction`, every type of `types` then has that friction.
Status mergeSceneTypes(const Scene& scene, BrickTypeLibrary* types);

/// The world options `scene` runs in: `options` with the scene's table when
/// it has one, and the scene's `friction` as the table's (the floor takes the
/// table's).
WorldOptions sceneWorldOptions(const Scene& scene, const WorldOptions& options);

/// A scene of `types` alone and no bricks, as YAML that parseScene() reads
/// back into the same shapes, masses and materials (inertia from the solid):
/// how a client hands a simulator the types a scene defines.
std::string typesAsScene(const std::vector<BrickType>& types);

/// `scene` as YAML that parseScene() reads back into the same scene: its
/// name, expected outcome, table, friction and types, and every brick by id,
/// type, time, position, orientation (a quaternion, to the last bit of a
/// double) and velocities. Generators and pose noise are not written: their
/// bricks are, as `bricks` holds them.
std::string sceneAsYaml(const Scene& scene);

}  // namespace brick_stack_sim
