#pragma once
// The parameters of the teleop nodes, read from their private namespace with
// the core's OptionsReader: a wrong type, a bad value or a parameter the node
// does not know stops it with a message naming the parameter, as the
// simulator does.

#include <string>

#include <Eigen/Core>

#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/ros/interface_names.h"
#include "brick_stack_sim/teleop/keyboard_command.h"

namespace brick_stack_sim {
namespace teleop {

/// What both teleop nodes read.
struct TeleopOptions {
  std::string sim = ros_adapter::kDefaultNamespace;  ///< The simulator's private namespace.
  /// Where the ghost or cursor starts [m], frame world: above the table's centre.
  Eigen::Vector3d initial_position = Eigen::Vector3d(0.0, 0.0, 0.1);
  double initial_yaw = 0.0;    ///< [rad] about world z.
  double wait_for_sim = 30.0;  ///< How long to wait for the simulator at start [s].
};

/// The brick placer's parameters.
struct PlacerOptions {
  TeleopOptions teleop;
  std::string type;  ///< Type of the ghost at start; empty: the types' default type.
  /// ~initial_position was not given: once the simulator answers, the ghost
  /// moves beside the bricks it has (besideBricks()), where it hides none.
  bool start_beside = true;
  /// Brick types; empty: the simulator's own ~types_urdf / ~materials_yaml,
  /// else the package's urdf/bricks.urdf and config/bricks.yaml.
  std::string types_urdf;
  std::string materials_yaml;
};

/// The keyboard teleop's parameters.
struct KeyboardOptions {
  TeleopOptions teleop;
  CursorSteps steps;  ///< Keys ~linear_step [m], ~angular_step [rad]; min_z is the table top.
  double held_target_rate = 10.0;  ///< ~held_target is repeated at this rate while holding [Hz].
};

Status validate(const TeleopOptions& options);
Status validate(const PlacerOptions& options);
Status validate(const KeyboardOptions& options);

/// Reads the node's private parameters `parameters` (readPrivateParameters)
/// over the defaults in `*options`; on failure `*options` is unchanged and
/// the message starts with "parameter ~<name>".
Status loadPlacerOptions(const ParameterValue& parameters, PlacerOptions* options);
Status loadKeyboardOptions(const ParameterValue& parameters, KeyboardOptions* options);

/// The brick types the simulator at `options.teleop.sim` uses, loaded as the
/// simulator loads them (BrickTypeLibrary::load of a URDF and a materials
/// yaml): the files named by the placer's ~types_urdf and ~materials_yaml,
/// else by the simulator's parameters of the same names, else the package's
/// defaults (resolveDataPaths). Fails, naming where the files came from, when
/// they cannot be read or `options.type` is not among them. Needs a master.
Status loadPlacerTypes(const PlacerOptions& options, BrickTypeLibrary* types);

}  // namespace teleop
}  // namespace brick_stack_sim
