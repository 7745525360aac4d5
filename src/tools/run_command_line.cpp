#include "brick_stack_sim/tools/run_command_line.h"

#include <cmath>
#include <cstdlib>
#include <set>

#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/types/stability_modes.h"

namespace brick_stack_sim {

namespace {

Status parseDouble(const std::string& flag, const std::string& text, double* value) {
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(parsed))
    return Status::error(flag + " expects a finite number, got '" + text + "'");
  *value = parsed;
  return Status::success();
}

Status parseInt(const std::string& flag, const std::string& text, int* value) {
  char* end = nullptr;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || parsed < -1000000000L || parsed > 1000000000L)
    return Status::error(flag + " expects an integer, got '" + text + "'");
  *value = static_cast<int>(parsed);
  return Status::success();
}

/// Each mode of the registry with what it does, one line each.
std::string modeLines() {
  std::string text;
  for (const std::string& mode : availableStabilityModes())
    text += "                        " + mode + ": " + describeStabilityMode(mode) + "\n";
  return text;
}

/// Flags with a value other than --config, in the order given.
using FlagValues = std::vector<std::pair<std::string, std::string>>;

// parseRunCommandLine's steps: the arguments are sorted first, and the flags
// applied once the config files are read.

/// Sorts the arguments: switches and --config files into `result` and
/// `no_sleep`, every other flag with its value into `overrides`. An unknown
/// flag, a stray argument or a flag without its value is an error.
Status collectFlags(const std::vector<std::string>& args, RunCommandLine* result, bool* no_sleep,
                    FlagValues* overrides) {
  static const std::set<std::string> kWithValue = {
      "--config",        "--scene",      "--mode",      "--duration",  "--time-step",
      "--iterations",    "--report",     "--types",     "--materials", "--scene-dir",
      "--fall-distance", "--fall-angle", "--save-scene"};
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--help" || flag == "-h") {
      result->help = true;
      continue;
    }
    if (flag == "--no-sleep") {
      *no_sleep = true;
      continue;
    }
    if (flag == "--skip-bad-bricks") {
      result->skip_bad_bricks = true;
      continue;
    }
    if (flag == "--statics") {
      result->statics = true;
      continue;
    }
    if (flag.rfind("--", 0) != 0) return Status::error("unexpected argument '" + flag + "'");
    if (!kWithValue.count(flag)) return Status::error("unknown option '" + flag + "' (see --help)");
    if (i + 1 >= args.size()) return Status::error(flag + " needs a value");
    const std::string& value = args[++i];
    if (flag == "--config") {
      result->config_files.push_back(value);
    } else {
      overrides->emplace_back(flag, value);
    }
  }
  return Status::success();
}

/// Applies the flags over the config files' settings in `result`; the
/// first malformed value is an error naming its flag.
Status applyFlags(const FlagValues& overrides, RunCommandLine* result) {
  WorldOptions& world = result->config.world;
  DataOptions& data = result->config.data;
  bool scene_dirs_given = false;
  for (const auto& [flag, value] : overrides) {
    Status parsed;
    if (flag == "--scene") {
      data.scene = value;
    } else if (flag == "--mode") {
      world.stability.mode = value;
      parsed = checkStabilityMode(value);
    } else if (flag == "--duration") {
      double duration = 0.0;
      parsed = parseDouble(flag, value, &duration);
      if (parsed && (duration < 0.0 || duration > kMaxSceneTime))
        parsed = Status::error("--duration must be in [0, " +
                               std::to_string(static_cast<long>(kMaxSceneTime)) + "] s");
      result->duration = duration;
    } else if (flag == "--time-step") {
      parsed = parseDouble(flag, value, &world.time_step);
    } else if (flag == "--iterations") {
      parsed = parseInt(flag, value, &world.solver_iterations);
    } else if (flag == "--fall-angle") {
      parsed = parseDouble(flag, value, &result->fall_angle);
      if (parsed && result->fall_angle <= 0.0)
        parsed = Status::error("--fall-angle must be > 0 rad, got '" + value + "'");
    } else if (flag == "--fall-distance") {
      parsed = parseDouble(flag, value, &result->fall_distance);
      if (parsed && result->fall_distance <= 0.0)
        parsed = Status::error("--fall-distance must be > 0 m, got '" + value + "'");
    } else if (flag == "--report") {
      result->report_path = value;
    } else if (flag == "--save-scene") {
      result->save_scene_path = value;
    } else if (flag == "--types") {
      data.types_urdf = value;
    } else if (flag == "--materials") {
      data.materials_yaml = value;
    } else if (flag == "--scene-dir") {
      // The flags replace the config's directories rather than add to them.
      if (!scene_dirs_given) data.scene_dirs.clear();
      scene_dirs_given = true;
      data.scene_dirs.push_back(value);
    }
    if (!parsed) return parsed;
  }
  return Status::success();
}

}  // namespace

std::string runUsage(const std::string& data_dir) {
  return "usage: stack_sim_run [--config YAML]... [--scene FILE|NAME] [options]\n"
         "Runs a scene with no ROS master and writes a JSON report.\n"
         "  --config YAML       the node's parameters (config/sim.yaml, config/stability.yaml);\n"
         "                      repeatable, later files override earlier ones key by key\n"
         "  --scene FILE|NAME   scene yaml, or a name from the scene directories\n"
         "                      (default: the config's `scene`)\n"
         "  --mode MODE         stability model (default: com), one of\n" +
         modeLines() +
         "  --duration S        simulated time [s] (default: last placement + 5 s)\n"
         "  --time-step S       fixed step [s] (default 0.001)\n"
         "  --iterations N      solver iterations per step (default 20)\n"
         "  --no-sleep          turn Bullet's own deactivation off (baselines)\n"
         "  --report FILE       write the JSON here (default: standard output); checked\n"
         "                      for writing before the run\n"
         "  --save-scene FILE   write the state the run ends in as a scene: every brick there\n"
         "                      at the end, at t = 0 where it was and with its velocities,\n"
         "                      to run again from there (bricks on the floor, which no scene\n"
         "                      can place, are left out and named); checked before the run\n"
         "  --skip-bad-bricks   run a scene with bricks that cannot be placed (bad pose,\n"
         "                      outside the world, overlapping...) without them and exit 0;\n"
         "                      by default such a scene is refused (exit 1)\n"
         "  --fall-distance D   a brick has fallen once its centre of mass moved more than\n"
         "                      D [m] from where it was placed (default 0.01)\n"
         "  --fall-angle A      or once it turned more than A [rad] (default 0.1)\n"
         "  --statics           add `statics`: whether the bricks placed first stand, by\n"
         "                      rigid-block statics (mode equilibrium's LP), and their margin\n"
         "  --types URDF        brick types (default: the package's urdf/bricks.urdf)\n"
         "  --materials YAML    friction and restitution per type (default: config/bricks.yaml)\n"
         "  --scene-dir DIR     where scene names are looked up (repeatable; default scenes/)\n"
         "  --help              this text\n"
         "Flags override the config files; bad values are refused with their name.\n" +
         (data_dir.empty() ? "" : "The package's urdf/, config/ and scenes/: " + data_dir + "\n");
}

Status parseRunCommandLine(const std::vector<std::string>& args, const std::string& data_dir,
                           RunCommandLine* command_line) {
  RunCommandLine result;
  // Flags are applied after the config files, whatever their order.
  FlagValues overrides;
  bool no_sleep = false;
  if (Status collected = collectFlags(args, &result, &no_sleep, &overrides); !collected)
    return collected;
  if (result.help) {
    *command_line = result;
    return Status::success();
  }
  if (!result.config_files.empty()) {
    if (Status loaded = loadSimulationConfig(result.config_files, &result.config); !loaded)
      return loaded;
  }
  if (no_sleep) result.config.world.sleeping.enabled = false;
  if (Status applied = applyFlags(overrides, &result); !applied) return applied;
  DataOptions& data = result.config.data;
  if (data.scene.empty())
    return Status::error("--scene is required (or a config with `scene`; see --help)");
  fillPackageData(data_dir, &data);
  if (Status valid = validate(result.config.world); !valid) {
    valid.message = "bad setting: " + valid.message;
    return valid;
  }
  *command_line = result;
  return Status::success();
}

}  // namespace brick_stack_sim
