#pragma once

#include <string>
#include <vector>

#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

class OptionsReader;

/// Where brick types and scenes come from.
struct DataOptions {
  std::string types_urdf;      ///< Brick types (geometry, mass, inertia); empty: the package's.
  std::string materials_yaml;  ///< Friction and restitution per type; empty: the package's.
  std::vector<std::string> scene_dirs;  ///< Where scene names are looked up; empty: the package's.
  std::string scene;  ///< Played at start (a name or a path); empty: an empty table.
  /// Largest scene file read [bytes]; a bigger one is refused unread.
  int scene_max_bytes = kDefaultSceneMaxBytes;
  /// Most bricks of one scene, counted before any is built; more are refused.
  int scene_max_bricks = kDefaultSceneMaxBricks;
};

/// Checks every field; the message names the first bad one by its key.
Status validate(const DataOptions& options);

/// The limits loadScene() applies: scene_max_bytes and scene_max_bricks.
SceneLimits sceneLimits(const DataOptions& options);

/// Fills the paths `data` leaves empty with the package's own data under
/// `package_dir` (the source tree or share/brick_stack_sim): the brick types
/// of urdf/bricks.urdf with the materials of config/bricks.yaml, and the
/// scenes of scenes/. The one place every program finds its defaults.
void fillPackageData(const std::string& package_dir, DataOptions* data);

/// How the ROS node publishes and paces the world. The batch runner reads
/// them too, and uses none, so that one yaml file serves both programs.
struct PublishOptions {
  double rate = 30.0;              ///< ~bricks, tf and markers per second of sim time [Hz].
  bool clock = false;              ///< Publish /clock so the graph can run on sim time.
  double real_time_factor = 1.0;   ///< Sim time per wall time [-]; 0: as fast as possible.
  std::string frame_id = "world";  ///< Fixed frame of every published pose.
  /// Put before every frame the node names on tf (bricks, the table), with a
  /// '/' between, so two simulators, or a robot with a frame called b0, do
  /// not clash: "sim1" gives "sim1/b0" (prefixedFrame).
  std::string frame_prefix;
  /// ~bricks carries, after a subscriber's first message (every brick),
  /// only the bricks that changed and the ids of those that went
  /// (BrickArray.msg's DELTA); false: every brick in every message.
  bool bricks_delta = false;
  /// The size of the RViz legend and mode title over the table, over the
  /// default one [-] (compare.launch shows two tables from further away).
  double legend_scale = 1.0;
};

/// Everything config/sim.yaml and config/stability.yaml hold: the one
/// options tree of the node (its private parameters) and of the runner
/// (stack_sim_run --config). Keys: the world's (WorldOptions) and
/// publish_rate, publish_clock, real_time_factor, frame_id, frame_prefix, bricks_delta,
/// legend_scale, types_urdf,
/// materials_yaml, scene_dirs, scene, scene_max_bytes and scene_max_bricks, all at the top.
struct SimulationConfig {
  WorldOptions world;
  DataOptions data;
  PublishOptions publish;
};

/// Checks every field; the message names the first bad one by its key.
/// `frame_id` may not be a frame the node names itself (its table, floor or
/// an unnamed brick's `brick_<n>` under the prefix): docs/ros_interface.md,
/// "Frames and units".
Status validate(const PublishOptions& options);

/// The tf frame the node names `name` (a brick id, or "table"): `frame_prefix`
/// and `name` joined by one '/', none when the prefix is empty or already
/// ends in '/' ("sim1" and "sim1/" both give "sim1/b0").
std::string prefixedFrame(const std::string& frame_prefix, const std::string& name);

/// Reads the whole tree at the reader's level; any key it does not know is
/// an error ("time_stepp is not a known parameter (known here: ...)"), and
/// so is a bad value ("time_step = -1: must be in [1e-5, 0.1] s"), named by
/// its path. `*config` changes only on success.
Status readSimulationConfig(OptionsReader& reader, SimulationConfig* config);

/// Reads yaml files into one tree, later files overriding earlier ones key
/// by key (as `rosparam load` of both into one namespace does), then reads
/// the tree over `*config`. Messages start with the files' names.
Status loadSimulationConfig(const std::vector<std::string>& yaml_paths, SimulationConfig* config);

}  // namespace brick_stack_sim
