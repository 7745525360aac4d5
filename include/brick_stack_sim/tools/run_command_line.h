#pragma once

#include <optional>
#include <string>
#include <vector>

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/world/world_options.h"

namespace brick_stack_sim {

/// The arguments of `stack_sim_run`, parsed and validated.
struct RunCommandLine {
  std::string scene;           ///< Scene file, or name looked up in scene_dirs.
  std::string report_path;     ///< Empty: the JSON goes to standard output.
  std::string types_urdf;      ///< Brick types; default: the package's urdf/bricks.urdf.
  std::string materials_yaml;  ///< Default: the package's config/bricks.yaml.
  std::vector<std::string> scene_dirs;
  std::optional<double> duration;  ///< [s]
  WorldOptions world;
  bool help = false;
};

/// Usage text of stack_sim_run.
std::string runUsage();

/// Parses argv (without argv[0]); `data_dir` is where the package's urdf/,
/// config/ and scenes/ live. An unknown flag, a missing or malformed value, or a
/// bad setting gives an error naming it.
Status parseRunCommandLine(const std::vector<std::string>& args, const std::string& data_dir,
                           RunCommandLine* command_line);

}  // namespace brick_stack_sim
