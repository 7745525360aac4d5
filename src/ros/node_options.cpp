#include "brick_stack_sim/ros/node_options.h"

#include <cmath>
#include <sstream>

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

using XmlRpc::XmlRpcValue;

/// A parameter's value in words, for messages ("string 'abc'", "array of 3").
std::string describe(const XmlRpcValue& value) {
  // XmlRpcValue's conversions are non-const; a copy keeps the caller's intact.
  XmlRpcValue copy = value;
  std::ostringstream text;
  switch (copy.getType()) {
    case XmlRpcValue::TypeBoolean:
      text << "bool " << (static_cast<bool&>(copy) ? "true" : "false");
      break;
    case XmlRpcValue::TypeInt:
      text << "int " << static_cast<int&>(copy);
      break;
    case XmlRpcValue::TypeDouble:
      text << "double " << static_cast<double&>(copy);
      break;
    case XmlRpcValue::TypeString:
      text << "string '" << static_cast<std::string&>(copy) << "'";
      break;
    case XmlRpcValue::TypeArray:
      text << "a list of " << copy.size();
      break;
    case XmlRpcValue::TypeStruct:
      text << "a dictionary";
      break;
    default:
      text << "a value of XML-RPC type " << static_cast<int>(copy.getType());
      break;
  }
  return text.str();
}

Status wrongType(const std::string& name, const XmlRpcValue& value, const char* expected) {
  return Status::error("parameter ~" + name + " is " + describe(value) + ", expected " + expected);
}

/// Converts one XML-RPC number; false for any other type.
bool toDouble(const XmlRpcValue& value, double* out) {
  XmlRpcValue copy = value;
  if (copy.getType() == XmlRpcValue::TypeDouble) {
    *out = static_cast<double&>(copy);
    return true;
  }
  if (copy.getType() == XmlRpcValue::TypeInt) {
    *out = static_cast<int&>(copy);
    return true;
  }
  return false;
}

template <typename T>
std::string str(const T& value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

Status bad(const std::string& name, const std::string& value, const std::string& requirement) {
  return Status::error("parameter ~" + name + " = " + value + ": " + requirement);
}

bool positive(double value) { return std::isfinite(value) && value > 0.0; }

// Small helpers so that loadNodeOptions reads as a list of parameters: each
// leaves the default alone when the parameter is not set.
struct Loader {
  const ParameterReader& params;
  Status status;

  template <typename T>
  void read(const std::string& name, Status (ParameterReader::*get)(const std::string&, T*) const,
            T* value) {
    if (!status || !params.has(name)) return;
    status = (params.*get)(name, value);
  }
  void number(const std::string& name, double* value) {
    read(name, &ParameterReader::getDouble, value);
  }
  void integer(const std::string& name, int* value) { read(name, &ParameterReader::getInt, value); }
  void boolean(const std::string& name, bool* value) {
    read(name, &ParameterReader::getBool, value);
  }
  void text(const std::string& name, std::string* value) {
    read(name, &ParameterReader::getString, value);
  }
  void texts(const std::string& name, std::vector<std::string>* value) {
    read(name, &ParameterReader::getStringList, value);
  }
};

}  // namespace

bool XmlRpcParameterReader::has(const std::string& name) const {
  XmlRpcValue value;
  return lookup(name, &value);
}

Status XmlRpcParameterReader::getDouble(const std::string& name, double* value) const {
  XmlRpcValue raw;
  if (!lookup(name, &raw)) return Status::error("parameter ~" + name + " is not set");
  if (!toDouble(raw, value)) return wrongType(name, raw, "a number");
  return Status::success();
}

Status XmlRpcParameterReader::getInt(const std::string& name, int* value) const {
  XmlRpcValue raw;
  if (!lookup(name, &raw)) return Status::error("parameter ~" + name + " is not set");
  if (raw.getType() != XmlRpcValue::TypeInt) return wrongType(name, raw, "an integer");
  *value = static_cast<int&>(raw);
  return Status::success();
}

Status XmlRpcParameterReader::getBool(const std::string& name, bool* value) const {
  XmlRpcValue raw;
  if (!lookup(name, &raw)) return Status::error("parameter ~" + name + " is not set");
  if (raw.getType() != XmlRpcValue::TypeBoolean) return wrongType(name, raw, "true or false");
  *value = static_cast<bool&>(raw);
  return Status::success();
}

Status XmlRpcParameterReader::getString(const std::string& name, std::string* value) const {
  XmlRpcValue raw;
  if (!lookup(name, &raw)) return Status::error("parameter ~" + name + " is not set");
  if (raw.getType() != XmlRpcValue::TypeString) return wrongType(name, raw, "a string");
  *value = static_cast<std::string&>(raw);
  return Status::success();
}

Status XmlRpcParameterReader::getDoubleList(const std::string& name,
                                            std::vector<double>* value) const {
  XmlRpcValue raw;
  if (!lookup(name, &raw)) return Status::error("parameter ~" + name + " is not set");
  if (raw.getType() != XmlRpcValue::TypeArray) return wrongType(name, raw, "a list of numbers");
  std::vector<double> result(raw.size());
  for (int i = 0; i < raw.size(); ++i) {
    if (!toDouble(raw[i], &result[i])) {
      return Status::error("parameter ~" + name + "[" + std::to_string(i) + "] is " +
                           describe(raw[i]) + ", expected a number");
    }
  }
  *value = std::move(result);
  return Status::success();
}

Status XmlRpcParameterReader::getStringList(const std::string& name,
                                            std::vector<std::string>* value) const {
  XmlRpcValue raw;
  if (!lookup(name, &raw)) return Status::error("parameter ~" + name + " is not set");
  if (raw.getType() != XmlRpcValue::TypeArray) return wrongType(name, raw, "a list of strings");
  std::vector<std::string> result;
  for (int i = 0; i < raw.size(); ++i) {
    XmlRpcValue item = raw[i];
    if (item.getType() != XmlRpcValue::TypeString) {
      return Status::error("parameter ~" + name + "[" + std::to_string(i) + "] is " +
                           describe(item) + ", expected a string");
    }
    result.push_back(static_cast<std::string&>(item));
  }
  *value = std::move(result);
  return Status::success();
}

bool RosParameterReader::lookup(const std::string& name, XmlRpc::XmlRpcValue* value) const {
  return node_handle_.getParam(name, *value);
}

bool MapParameterReader::lookup(const std::string& name, XmlRpc::XmlRpcValue* value) const {
  auto found = values_.find(name);
  if (found == values_.end()) return false;
  *value = found->second;
  return true;
}

Status validate(const NodeOptions& options) {
  // Above 10 kHz of sim time a subscriber learns nothing more and the node
  // spends its time serialising.
  if (!positive(options.publish_rate) || options.publish_rate > 10000.0)
    return bad("publish_rate", str(options.publish_rate), "must be in (0, 10000] Hz");
  if (!std::isfinite(options.real_time_factor) || options.real_time_factor < 0.0 ||
      options.real_time_factor > 1e6)
    return bad("real_time_factor", str(options.real_time_factor),
               "must be in [0, 1e6] (0: as fast as possible)");
  // tf2 refuses frame ids with a leading slash; an empty one matches nothing.
  if (options.frame_id.empty() || options.frame_id.front() == '/' ||
      options.frame_id.find_first_of(" \t\n") != std::string::npos)
    return bad("frame_id", "'" + options.frame_id + "'",
               "must be a non-empty tf frame id without a leading '/' or spaces");
  if (Status available = checkStabilityModeAvailable(options.world.mode); !available)
    return bad("stability/mode", std::string("'") + toString(options.world.mode) + "'",
               available.message);
  // The core's messages name its fields like our parameters ("time_step = ...").
  if (Status world = brick_stack_sim::validate(options.world); !world)
    return Status::error("parameter ~" + world.message);
  return Status::success();
}

WorldOptions defaultNodeWorldOptions() {
  WorldOptions world;
  world.mode = StabilityMode::kCom;
  return world;
}

Status loadNodeOptions(const ParameterReader& params, NodeOptions* options) {
  NodeOptions result = *options;
  WorldOptions& world = result.world;
  Loader load{params, Status::success()};

  load.number("time_step", &world.time_step);
  load.integer("solver_iterations", &world.solver_iterations);
  load.number("gravity", &world.gravity);
  load.number("publish_rate", &result.publish_rate);
  load.boolean("publish_clock", &result.publish_clock);
  load.number("real_time_factor", &result.real_time_factor);
  load.text("frame_id", &result.frame_id);

  std::string mode = toString(world.mode);
  load.text("stability/mode", &mode);
  if (!load.status) return load.status;
  if (Status parsed = parseStabilityMode(mode, &world.mode); !parsed)
    return bad("stability/mode", "'" + mode + "'", parsed.message);
  // Read in every mode so that a bad value is refused even while unused.
  StabilityOptions& stability = world.stability;
  load.number("stability/rest_linear_speed", &stability.rest_linear_speed);
  load.number("stability/rest_angular_speed", &stability.rest_angular_speed);
  load.number("stability/rest_time", &stability.rest_time);
  load.number("stability/impact_speed", &stability.impact_speed);
  load.number("stability/support_normal_tolerance", &stability.support_normal_tolerance);
  load.number("stability/flush_angle", &stability.flush_angle);
  load.number("stability/contact_distance", &stability.contact_distance);
  load.number("stability/min_margin", &stability.min_margin);

  load.boolean("sleeping/enabled", &world.sleeping);
  load.number("sleeping/linear_threshold", &world.linear_sleep_threshold);
  load.number("sleeping/angular_threshold", &world.angular_sleep_threshold);
  load.number("sleeping/time", &world.deactivation_time);

  if (load.status && params.has("table/size")) {
    std::vector<double> size;
    load.status = params.getDoubleList("table/size", &size);
    if (!load.status) return load.status;
    if (size.size() != 2)
      return bad("table/size", "a list of " + std::to_string(size.size()),
                 "must be a list of 2 numbers [x, y] in m");
    world.table.size = Eigen::Vector2d(size[0], size[1]);
  }
  load.number("table/thickness", &world.table.thickness);
  load.number("table/height", &world.table.height);
  load.number("table/friction", &world.table.friction);
  load.number("table/restitution", &world.table.restitution);
  load.number("overlap_tolerance", &world.overlap_tolerance);
  load.number("fall_off_depth", &world.fall_off_depth);

  load.text("types_urdf", &result.types_urdf);
  load.text("materials_yaml", &result.materials_yaml);
  load.texts("scene_dirs", &result.scene_dirs);
  load.text("scene", &result.initial_scene);
  if (!load.status) return load.status;

  if (Status valid = validate(result); !valid) return valid;
  *options = std::move(result);
  return Status::success();
}

Status resolveDataPaths(const std::string& package_dir, NodeOptions* options) {
  if (!package_dir.empty()) {
    if (options->types_urdf.empty()) options->types_urdf = package_dir + "/urdf/bricks.urdf";
    if (options->materials_yaml.empty())
      options->materials_yaml = package_dir + "/config/bricks.yaml";
    if (options->scene_dirs.empty()) options->scene_dirs.push_back(package_dir + "/scenes");
  }
  if (options->types_urdf.empty())
    return Status::error(
        "parameter ~types_urdf is not set and the package brick_stack_sim was not found to "
        "supply urdf/bricks.urdf; set ~types_urdf to the URDF of the brick types");
  return Status::success();
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
