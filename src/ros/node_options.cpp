#include "brick_stack_sim/ros/node_options.h"

#include "brick_stack_sim/core/options/options_reader.h"

namespace brick_stack_sim {
namespace ros_adapter {

Status loadNodeOptions(const ParameterValue& parameters, NodeOptions* options) {
  SimulationConfig config = options->config;
  OptionsReader reader(parameters);
  if (Status read = readSimulationConfig(reader, &config); !read)
    return prefixed("parameter ~", read);
  options->config = std::move(config);
  return Status::success();
}

Status resolveDataPaths(const std::string& package_dir, NodeOptions* options) {
  DataOptions& data = options->config.data;
  if (!package_dir.empty()) fillPackageData(package_dir, &data);
  if (data.types_urdf.empty())
    return Status::error(
        "parameter ~types_urdf is not set and the package brick_stack_sim was not found to "
        "supply urdf/bricks.urdf; set ~types_urdf to the URDF of the brick types");
  return Status::success();
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
