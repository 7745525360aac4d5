#pragma once

#include <string>

#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Everything the node needs to start: its private parameters
/// (docs/ros_interface.md, "Parameters"; config/sim.yaml and
/// config/stability.yaml, the same tree that stack_sim_run --config reads)
/// and how it paces the world.
struct NodeOptions {
  SimulationConfig config;
  /// ~simulate_plan requests run at once (parameter ~max_concurrent_plans,
  /// in [kMinConcurrentPlans, kMaxConcurrentPlans]); one more is refused. Each
  /// plan holds a copy of the world and a core while it runs.
  int max_concurrent_plans = 2;

  // Not parameters: how the node paces the world (node.cpp explains the values).
  double step_timer_rate = 200.0;  ///< Wall-time rate of the stepping timer [Hz].
  int max_steps_per_tick = 2000;   ///< Upper bound of world steps per timer tick.
  double max_step_budget = 0.8;    ///< Share of a timer period spent stepping [-].
};

/// The range of ~max_concurrent_plans: at least one plan, and no more
/// threads than a node should start for them.
constexpr int kMinConcurrentPlans = 1;
constexpr int kMaxConcurrentPlans = 64;

/// Success when `max_concurrent_plans` is in its range; otherwise the
/// message names the parameter ("parameter ~max_concurrent_plans = 0: ...").
Status validateMaxConcurrentPlans(int max_concurrent_plans);

/// Reads the node's private parameters (readPrivateParameters) over the
/// defaults of `*options` with the core's readers. A parameter the node does
/// not know, a value of the wrong type or out of range is refused with a
/// message naming it as the user typed it ("parameter ~time_stepp is not a
/// known parameter ...", "parameter ~time_step = -0.001: ..."), and
/// `*options` is left unchanged.
Status loadNodeOptions(const ParameterValue& parameters, NodeOptions* options);

/// Fills the data paths the parameters left empty from the package's directory
/// (`<package_dir>/urdf/bricks.urdf`, `config/bricks.yaml`, `scenes`), then
/// fails, naming the parameter, when `types_urdf` is still empty.
Status resolveDataPaths(const std::string& package_dir, NodeOptions* options);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
