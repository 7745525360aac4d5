// stack_sim_run: runs a scene with no ROS master and writes a JSON report.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/tools/package_data.h"
#include "brick_stack_sim/tools/run_command_line.h"

using namespace brick_stack_sim;

int main(int argc, char** argv) {
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
  RunOptions options;
  options.world = cli.config.world;
  options.duration = cli.duration;
  const DataOptions& data = cli.config.data;
  Status status = BrickTypeLibrary::load(data.types_urdf, data.materials_yaml, &types);
  if (status) status = loadScene(data.scene, data.scene_dirs, types, &scene, data.scene_max_bytes);
  if (status) status = runScene(scene, types, options, &report);
  if (!status) {
    std::cerr << "stack_sim_run: " << status.message << "\n";
    return 1;
  }
  const std::string json = toJson(report);
  if (cli.report_path.empty()) {
    std::cout << json;
  } else if (!(std::ofstream(cli.report_path) << json)) {
    std::cerr << "stack_sim_run: cannot write report '" << cli.report_path << "'\n";
    return 1;
  }
  std::fprintf(stderr,
               "%s: mode %s, %.3f s simulated in %.3f s wall (real-time factor %.1f), %zu bricks, "
               "largest displacement %.3f mm, nonfinite %llu, refused %zu\n",
               report.scene.c_str(), report.world.stability.mode.c_str(), report.sim_time,
               report.wall_time, report.sim_time / std::max(report.wall_time, 1e-9),
               report.bricks.size(), report.maxDisplacement() * 1000.0,
               static_cast<unsigned long long>(report.cost.nonfinite), report.refused.size());
  return 0;
}
