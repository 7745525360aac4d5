#include "brick_stack_sim/teleop/teleop_options.h"

#include <cmath>

#include <ros/names.h>
#include <ros/package.h>
#include <ros/ros.h>

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/ros/interface_names.h"
#include "brick_stack_sim/ros/node_options.h"
#include "util/validation.h"

namespace brick_stack_sim {
namespace teleop {

namespace {

/// The largest step a key may make: one key press moving a brick by more
/// than this [m] is a unit mistake (millimetres typed as metres), not a wish.
constexpr double kMaxLinearStep = 0.5;

void readTeleopKeys(OptionsReader& reader, TeleopOptions* options) {
  reader.read("sim", &options->sim);
  reader.read("initial_position", &options->initial_position);
  reader.read("initial_yaw", &options->initial_yaw);
  reader.read("wait_for_sim", &options->wait_for_sim);
}

}  // namespace

Status validate(const TeleopOptions& o) {
  std::string error;
  if (o.sim.empty() || !ros::names::validate(o.sim, error))
    return bad("sim", "'" + o.sim + "'",
               std::string("must be the simulator's namespace, e.g. ") +
                   ros_adapter::kDefaultNamespace + (error.empty() ? "" : " (" + error + ")"));
  if (!o.initial_position.allFinite() || o.initial_position.z() < kTableTop)
    return bad("initial_position", o.initial_position.transpose(),
               "must be finite [m], z at or above the table top (0)");
  if (!std::isfinite(o.initial_yaw)) return bad("initial_yaw", o.initial_yaw, "must be finite rad");
  if (!nonNegative(o.wait_for_sim)) return bad("wait_for_sim", o.wait_for_sim, "must be >= 0 s");
  return Status::success();
}

Status validate(const PlacerOptions& o) { return validate(o.teleop); }

Status validate(const KeyboardOptions& o) {
  if (Status common = validate(o.teleop); !common) return common;
  if (!positive(o.steps.linear) || o.steps.linear > kMaxLinearStep)
    return bad("linear_step", o.steps.linear, "must be in (0, 0.5] m");
  if (!positive(o.steps.angular) || o.steps.angular > M_PI)
    return bad("angular_step", o.steps.angular, "must be in (0, pi] rad");
  if (!positive(o.held_target_rate))
    return bad("held_target_rate", o.held_target_rate, "must be > 0 Hz");
  return Status::success();
}

Status loadPlacerOptions(const ParameterValue& parameters, PlacerOptions* options) {
  OptionsReader reader(parameters);
  return prefixed("parameter ~", readAndValidate(reader, true, options, [&](PlacerOptions& o) {
                    readTeleopKeys(reader, &o.teleop);
                    o.start_beside = parameters.find("initial_position") == nullptr;
                    reader.read("type", &o.type);
                    reader.read("types_urdf", &o.types_urdf);
                    reader.read("materials_yaml", &o.materials_yaml);
                  }));
}

Status loadKeyboardOptions(const ParameterValue& parameters, KeyboardOptions* options) {
  OptionsReader reader(parameters);
  return prefixed("parameter ~", readAndValidate(reader, true, options, [&](KeyboardOptions& o) {
                    readTeleopKeys(reader, &o.teleop);
                    reader.read("linear_step", &o.steps.linear);
                    reader.read("angular_step", &o.steps.angular);
                    reader.read("held_target_rate", &o.held_target_rate);
                  }));
}

Status loadPlacerTypes(const PlacerOptions& options, BrickTypeLibrary* types) {
  // The simulator's own parameters first: the ghost must have the sizes of
  // the bricks the simulator will create.
  ros_adapter::NodeOptions sim_options;
  DataOptions& data = sim_options.config.data;
  const ros::NodeHandle sim(options.teleop.sim);
  // Where each file name came from, for the message of a failure.
  auto choose = [&](const std::string& own, const std::string& key, std::string* path) {
    *path = own;
    if (!path->empty()) return "~" + key;
    if (sim.getParam(key, *path) && !path->empty()) return options.teleop.sim + "/" + key;
    path->clear();
    return std::string("the package's default ") + key;
  };
  const std::string urdf_source = choose(options.types_urdf, "types_urdf", &data.types_urdf);
  const std::string materials_source =
      choose(options.materials_yaml, "materials_yaml", &data.materials_yaml);
  if (Status resolved =
          ros_adapter::resolveDataPaths(ros::package::getPath("brick_stack_sim"), &sim_options);
      !resolved)
    return resolved;
  BrickTypeLibrary loaded;
  if (Status read = BrickTypeLibrary::load(data.types_urdf, data.materials_yaml, &loaded); !read)
    return Status::error("brick types from " + urdf_source + " = '" + data.types_urdf + "', " +
                         materials_source + " = '" + data.materials_yaml + "': " + read.message);
  if (!options.type.empty() && !loaded.find(options.type)) {
    std::string known;
    for (const std::string& name : loaded.names()) known += (known.empty() ? "" : ", ") + name;
    return Status::error("parameter ~type = '" + options.type + "': not a brick type of '" +
                         data.types_urdf + "' (known: " + known + ")");
  }
  *types = std::move(loaded);
  return Status::success();
}

}  // namespace teleop
}  // namespace brick_stack_sim
