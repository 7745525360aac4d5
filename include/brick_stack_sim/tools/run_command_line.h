#pragma once

#include <optional>
#include <string>
#include <vector>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// The arguments of `stack_sim_run`, parsed and validated.
struct RunCommandLine {
  /// The node's options tree: the defaults, then the --config files, then
  /// the flags. Its data paths are filled from the package where left empty.
  SimulationConfig config;
  std::vector<std::string> config_files;  ///< --config, in order.
  std::string report_path;                ///< Empty: the JSON goes to standard output.
  /// Where the state the run ends in is written as a scene; empty: nowhere.
  std::string save_scene_path;
  std::optional<double> duration;  ///< [s]
  /// Run a scene with bricks that cannot be placed without them (and exit 0)
  /// instead of refusing it.
  bool skip_bad_bricks = false;
  /// --statics: judge the scene's first structure by statics (the report's `statics`).
  bool statics = false;
  /// --fall-distance: a brick has fallen once its centre of mass moved farther [m].
  double fall_distance = kDefaultFallDistance;
  /// --fall-angle: or once it turned farther [rad].
  double fall_angle = kDefaultFallAngle;
  bool help = false;
};

/// Usage text of stack_sim_run; names `data_dir`, where the defaults come
/// from, when given (devel or install space: see packageDataDir()).
std::string runUsage(const std::string& data_dir = "");

/// Parses argv (without argv[0]); `data_dir` is where the package's urdf/,
/// config/ and scenes/ live. An unknown flag, a missing or malformed value, or a
/// bad setting gives an error naming it. The scene is `--scene`, else the
/// config's `scene`; one of them is required.
Status parseRunCommandLine(const std::vector<std::string>& args, const std::string& data_dir,
                           RunCommandLine* command_line);

}  // namespace brick_stack_sim
