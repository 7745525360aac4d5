#pragma once

#include <map>
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/world/world_options.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// The world options the node starts from: the core's defaults with the stack
/// stability layer on (mode com), because that layer is why users pick this
/// package; `stability/mode: none` is the plain-Bullet baseline.
WorldOptions defaultNodeWorldOptions();

/// Everything the node needs to start, read from its private parameters
/// (DESIGN.md section 3). Defaults are those of defaultNodeWorldOptions() and
/// config/sim.yaml, config/stability.yaml.
struct NodeOptions {
  WorldOptions world = defaultNodeWorldOptions();
  double publish_rate = 30.0;           ///< ~bricks, tf and markers per second of sim time [Hz].
  bool publish_clock = false;           ///< Publish /clock so the graph can run on sim time.
  double real_time_factor = 1.0;        ///< Sim time per wall time [-]; 0 = as fast as possible.
  std::string frame_id = "world";       ///< Fixed frame of every pose the node publishes.
  std::string types_urdf;               ///< Brick types (geometry, mass, inertia); required.
  std::string materials_yaml;           ///< Friction and restitution per type; may be empty.
  std::vector<std::string> scene_dirs;  ///< Where ~reset and ~scene look up scene names.
  std::string initial_scene;            ///< Played at start; empty: an empty table.

  // Not parameters: how the node paces the world (node.cpp explains the values).
  double step_timer_rate = 200.0;  ///< Wall-time rate of the stepping timer [Hz].
  int max_steps_per_tick = 2000;   ///< Upper bound of world steps per timer tick.
  double max_step_budget = 0.8;    ///< Share of a timer period spent stepping [-].
};

/// Reads named parameters of one namespace. Getters are only called for names
/// that has() reports; they fail with a message naming the parameter when the
/// value has the wrong type, and leave `*value` unchanged then. An integer is
/// accepted where a double is expected (YAML writes 10 for 10.0), nothing else
/// is converted.
class ParameterReader {
 public:
  virtual ~ParameterReader() = default;
  virtual bool has(const std::string& name) const = 0;
  virtual Status getDouble(const std::string& name, double* value) const = 0;
  virtual Status getInt(const std::string& name, int* value) const = 0;
  virtual Status getBool(const std::string& name, bool* value) const = 0;
  virtual Status getString(const std::string& name, std::string* value) const = 0;
  virtual Status getDoubleList(const std::string& name, std::vector<double>* value) const = 0;
  virtual Status getStringList(const std::string& name, std::vector<std::string>* value) const = 0;
};

/// Type checks and conversions shared by the readers below: both see the
/// parameter server's XML-RPC values, so the unit tests over a map exercise
/// exactly the conversions the node uses.
class XmlRpcParameterReader : public ParameterReader {
 public:
  bool has(const std::string& name) const override;
  Status getDouble(const std::string& name, double* value) const override;
  Status getInt(const std::string& name, int* value) const override;
  Status getBool(const std::string& name, bool* value) const override;
  Status getString(const std::string& name, std::string* value) const override;
  Status getDoubleList(const std::string& name, std::vector<double>* value) const override;
  Status getStringList(const std::string& name, std::vector<std::string>* value) const override;

 protected:
  /// Copies the value of `name` into `*value`; false when there is none.
  virtual bool lookup(const std::string& name, XmlRpc::XmlRpcValue* value) const = 0;
};

/// Parameters of a ros::NodeHandle's namespace (the node's private one).
class RosParameterReader : public XmlRpcParameterReader {
 public:
  explicit RosParameterReader(const ros::NodeHandle& node_handle) : node_handle_(node_handle) {}

 protected:
  bool lookup(const std::string& name, XmlRpc::XmlRpcValue* value) const override;

 private:
  ros::NodeHandle node_handle_;
};

/// Parameters held in a map, keyed like the private names ("table/size"); for
/// tests that run with no master.
class MapParameterReader : public XmlRpcParameterReader {
 public:
  MapParameterReader() = default;
  explicit MapParameterReader(std::map<std::string, XmlRpc::XmlRpcValue> values)
      : values_(std::move(values)) {}
  void set(const std::string& name, const XmlRpc::XmlRpcValue& value) { values_[name] = value; }

 protected:
  bool lookup(const std::string& name, XmlRpc::XmlRpcValue* value) const override;

 private:
  std::map<std::string, XmlRpc::XmlRpcValue> values_;
};

/// Reads every parameter of DESIGN.md section 3 that is set (a missing one
/// keeps its default) and validates the result. On failure the message names
/// the parameter and its value, e.g. "parameter ~time_step = -0.001: ...",
/// and `*options` is left unchanged.
Status loadNodeOptions(const ParameterReader& params, NodeOptions* options);

/// Fills the data paths the parameters left empty from the package's directory
/// (`<package_dir>/urdf/bricks.urdf`, `config/bricks.yaml`, `scenes`), then
/// fails, naming the parameter, when `types_urdf` is still empty.
Status resolveDataPaths(const std::string& package_dir, NodeOptions* options);

/// Checks the options the adapter adds to WorldOptions, then the world's.
Status validate(const NodeOptions& options);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
