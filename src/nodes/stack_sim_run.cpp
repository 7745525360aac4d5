// stack_sim_run: runs a scene with no ROS master and writes a JSON report.
#include <cstdio>
#include <fstream>
#include <iostream>

#include <unistd.h>

#include "brick_stack_sim/core/allocation_guard.h"
#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/io/end_state_scene.h"
#include "brick_stack_sim/tools/package_data.h"
#include "brick_stack_sim/tools/run_command_line.h"

using namespace brick_stack_sim;

namespace {

/// Whether `path` (empty: standard output or nowhere) can be written, without
/// leaving a file behind that was not there; `what` names it in the message.
Status checkWritable(const std::string& path, const std::string& what) {
  if (path.empty()) return Status::success();
  // access(), not opening it: reading a FIFO would block.
  const bool existed = ::access(path.c_str(), F_OK) == 0;
  const bool writable = static_cast<bool>(std::ofstream(path, std::ios::app));
  if (!existed && writable) std::remove(path.c_str());
  if (!writable) return Status::error("cannot write " + what + " '" + path + "'");
  return Status::success();
}

/// Refuses a scene with bricks that can never be placed, naming the first;
/// with --skip-bad-bricks takes them out of `scene` into `skipped` instead.
Status skipOrRefuseBadBricks(const RunCommandLine& cli, Scene* scene, const BrickTypeLibrary& types,
                             const WorldOptions& world, std::vector<RefusedPlacement>* skipped) {
  std::vector<BadSceneBrick> bad;
  if (Status checked = findBadSceneBricks(*scene, types, world, &bad); !checked) return checked;
  if (bad.empty()) return Status::success();
  if (!cli.skip_bad_bricks) {
    const ScheduledBrick& first = scene->bricks[bad.front().index];
    return Status::error(
        "scene '" + cli.config.data.scene + "': " + std::to_string(bad.size()) +
        " brick(s) can never be placed, the first (" + std::to_string(bad.front().index + 1) +
        " of " + std::to_string(scene->bricks.size()) + ", id '" + first.placement.id +
        "'): " + bad.front().reason + " (--skip-bad-bricks runs the scene without them)");
  }
  for (SetAsideBrick& aside : setAsideBadBricks(bad, scene))
    skipped->push_back(RefusedPlacement{aside.brick.at, aside.brick.placement.id, aside.reason});
  return Status::success();
}

/// Writes the state `report` ended in as a scene to `path`, saying on
/// standard error what it wrote and what it left out.
Status saveEndState(const std::string& path, const Scene& scene, const RunReport& report,
                    const BrickTypeLibrary& types, const WorldOptions& world) {
  Scene end_state;
  std::vector<SetAsideBrick> left_out;
  if (Status made = endStateScene(scene, report, types, world, &end_state, &left_out); !made)
    return made;
  if (!(std::ofstream(path) << sceneAsYaml(end_state)))
    return Status::error("cannot write scene '" + path + "'");
  std::cerr << "stack_sim_run: wrote the state at t = " << report.sim_time << " s to '" << path
            << "': " << end_state.bricks.size() << " brick(s)";
  if (!left_out.empty())
    std::cerr << ", " << left_out.size() << " left out that no scene can place, the first "
              << left_out.front().brick.placement.id << ": " << left_out.front().reason;
  std::cerr << "\n";
  return Status::success();
}

/// Writes the report (to standard output without a path) and, when asked,
/// the state the run ended in.
Status writeResults(const RunCommandLine& cli, const Scene& scene, const RunReport& report,
                    const BrickTypeLibrary& types, const WorldOptions& world) {
  const std::string json = toJson(report);
  if (cli.report_path.empty())
    std::cout << json;
  else if (!(std::ofstream(cli.report_path) << json))
    return Status::error("cannot write report '" + cli.report_path + "'");
  if (cli.save_scene_path.empty()) return Status::success();
  return saveEndState(cli.save_scene_path, scene, report, types, world);
}

/// What the command line asks of the run.
RunOptions runOptionsOf(const RunCommandLine& cli) {
  RunOptions options;
  options.world = cli.config.world;
  options.duration = cli.duration;
  options.fall_distance = cli.fall_distance;
  options.fall_angle = cli.fall_angle;
  options.statics = cli.statics;
  return options;
}

/// The whole run; main() turns an allocation failure into exit 1.
int run(int argc, char** argv) {
  RunCommandLine cli;
  const std::vector<std::string> args(argv + 1, argv + argc);
  const std::string data_dir = packageDataDir(BRICK_STACK_SIM_DATA_DIR);
  if (Status parsed = parseRunCommandLine(args, data_dir, &cli); !parsed) {
    std::cerr << "stack_sim_run: " << parsed.message << "\n";
    return 2;
  }
  if (cli.help) {
    std::cout << runUsage(data_dir);
    return 0;
  }
  BrickTypeLibrary types;
  Scene scene;
  RunReport report;
  const RunOptions options = runOptionsOf(cli);
  const DataOptions& data = cli.config.data;
  // A report or scene that cannot be written is found out before a long run,
  // not after.
  Status status = checkWritable(cli.report_path, "report");
  if (status) status = checkWritable(cli.save_scene_path, "scene");
  if (status) status = BrickTypeLibrary::load(data.types_urdf, data.materials_yaml, &types);
  if (status) status = loadScene(data.scene, data.scene_dirs, types, &scene, sceneLimits(data));
  std::vector<RefusedPlacement> skipped;
  if (status) status = skipOrRefuseBadBricks(cli, &scene, types, options.world, &skipped);
  if (status) status = runScene(scene, types, options, &report);
  if (!status) {
    std::cerr << "stack_sim_run: " << status.message << "\n";
    return 1;
  }
  // The bricks set aside were scheduled and refused like any other.
  report.scheduled += skipped.size();
  report.refused.insert(report.refused.begin(), skipped.begin(), skipped.end());
  if (Status written = writeResults(cli, scene, report, types, options.world); !written) {
    std::cerr << "stack_sim_run: " << written.message << "\n";
    return 1;
  }
  std::fprintf(stderr,
               "%s: mode %s, %.3f s simulated in %.3f s wall (real-time factor %.1f), %zu brick%s, "
               "largest displacement %.3f mm, nonfinite %llu, refused %zu\n",
               report.scene.c_str(), report.world.stability.mode.c_str(), report.sim_time,
               report.wall_time, report.sim_time / std::max(report.wall_time, 1e-9),
               report.bricks.size(), report.bricks.size() == 1 ? "" : "s",
               report.maxDisplacement() * 1000.0,
               static_cast<unsigned long long>(report.cost.nonfinite), report.refused.size());
  // Refused during the run (an overlap with a brick placed earlier): the
  // scene did not run as written.
  if (!report.refused.empty() && !cli.skip_bad_bricks) {
    const RefusedPlacement& first = report.refused.front();
    std::cerr << "stack_sim_run: " << report.refused.size()
              << " brick(s) of the scene could not be placed, the first " << first.id
              << " at t=" << first.t << " s: " << first.reason
              << " (--skip-bad-bricks accepts that)\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // A scene too large for the memory there is fails the run with a message
  // (docs/ros_interface.md, "stack_sim_run"), never with an abort.
  int code = 1;
  const Status guarded = refuseOnAllocationFailure("running the scene", [&] {
    code = run(argc, argv);
    return Status::success();
  });
  if (guarded) return code;
  std::cerr << "stack_sim_run: " << guarded.message << "\n";
  return 1;
}
