#include "brick_stack_sim/ros/node_options.h"

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/ros/interface_names.h"

namespace brick_stack_sim {
namespace ros_adapter {

Status validateMaxConcurrentPlans(int max_concurrent_plans) {
  if (max_concurrent_plans >= kMinConcurrentPlans && max_concurrent_plans <= kMaxConcurrentPlans)
    return Status::success();
  return Status::error("parameter ~" + std::string(kMaxConcurrentPlansParameter) + " = " +
                       std::to_string(max_concurrent_plans) + ": must be in [" +
                       std::to_string(kMinConcurrentPlans) + ", " +
                       std::to_string(kMaxConcurrentPlans) + "] (plans run at once)");
}

Status loadNodeOptions(const ParameterValue& parameters, NodeOptions* options) {
  SimulationConfig config = options->config;
  OptionsReader reader(parameters);
  // The node's own key, read first on the same reader so that the tree's
  // reader counts it as known (stack_sim_run, which reads the same tree
  // from its files, has no plans).
  int max_concurrent_plans = options->max_concurrent_plans;
  reader.read(kMaxConcurrentPlansParameter, &max_concurrent_plans);
  if (!reader.ok()) return prefixed("parameter ~", reader.finish());
  if (Status valid = validateMaxConcurrentPlans(max_concurrent_plans); !valid) return valid;
  if (Status read = readSimulationConfig(reader, &config); !read)
    return prefixed("parameter ~", read);
  options->config = std::move(config);
  options->max_concurrent_plans = max_concurrent_plans;
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
