#include "brick_stack_sim/tools/run_command_line.h"

#include <cmath>
#include <cstdlib>

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

}  // namespace

std::string runUsage() {
  return "usage: stack_sim_run --scene FILE|NAME [options]\n"
         "Runs a scene with no ROS master and writes a JSON report.\n"
         "  --scene FILE|NAME   scene yaml, or a name from the scene directories\n"
         "  --mode MODE         stability model: none (default), com, equilibrium\n"
         "  --duration S        simulated time [s] (default: last placement + 5 s)\n"
         "  --time-step S       fixed step [s] (default 0.001)\n"
         "  --iterations N      solver iterations per step (default 20)\n"
         "  --no-sleep          turn Bullet's own deactivation off (baselines)\n"
         "  --report FILE       write the JSON here (default: standard output)\n"
         "  --types URDF        brick types (default: the package's urdf/bricks.urdf)\n"
         "  --materials YAML    friction and restitution per type (default: config/bricks.yaml)\n"
         "  --scene-dir DIR     where scene names are looked up (repeatable; default scenes/)\n"
         "  --help              this text\n";
}

Status parseRunCommandLine(const std::vector<std::string>& args, const std::string& data_dir,
                           RunCommandLine* command_line) {
  RunCommandLine result;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--help" || flag == "-h") {
      result.help = true;
      continue;
    }
    if (flag == "--no-sleep") {
      result.world.sleeping = false;
      continue;
    }
    if (flag.rfind("--", 0) != 0) return Status::error("unexpected argument '" + flag + "'");
    static const char* kWithValue[] = {"--scene",     "--mode",       "--duration",
                                       "--time-step", "--iterations", "--report",
                                       "--types",     "--materials",  "--scene-dir"};
    bool known = false;
    for (const char* candidate : kWithValue) known = known || flag == candidate;
    if (!known) return Status::error("unknown option '" + flag + "' (see --help)");
    if (i + 1 >= args.size()) return Status::error(flag + " needs a value");
    const std::string& value = args[++i];
    Status parsed;
    if (flag == "--scene") {
      result.scene = value;
    } else if (flag == "--mode") {
      parsed = parseStabilityMode(value, &result.world.mode);
    } else if (flag == "--duration") {
      double duration = 0.0;
      parsed = parseDouble(flag, value, &duration);
      if (parsed && duration < 0.0) parsed = Status::error("--duration must be >= 0 s");
      result.duration = duration;
    } else if (flag == "--time-step") {
      parsed = parseDouble(flag, value, &result.world.time_step);
    } else if (flag == "--iterations") {
      parsed = parseInt(flag, value, &result.world.solver_iterations);
    } else if (flag == "--report") {
      result.report_path = value;
    } else if (flag == "--types") {
      result.types_urdf = value;
    } else if (flag == "--materials") {
      result.materials_yaml = value;
    } else if (flag == "--scene-dir") {
      result.scene_dirs.push_back(value);
    }
    if (!parsed) return parsed;
  }
  if (result.help) {
    *command_line = result;
    return Status::success();
  }
  if (result.scene.empty()) return Status::error("--scene is required (see --help)");
  if (result.types_urdf.empty()) result.types_urdf = data_dir + "/urdf/bricks.urdf";
  if (result.materials_yaml.empty()) result.materials_yaml = data_dir + "/config/bricks.yaml";
  if (result.scene_dirs.empty()) result.scene_dirs.push_back(data_dir + "/scenes");
  if (Status valid = validate(result.world); !valid) {
    valid.message = "bad setting: " + valid.message;
    return valid;
  }
  *command_line = result;
  return Status::success();
}

}  // namespace brick_stack_sim
