#include "brick_stack_sim/ros/xmlrpc_parameters.h"

#include <exception>
#include <utility>

#include "brick_stack_sim/core/options/yaml_parameters.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

/// Deeper nesting is refused: no parameter needs it, and the conversion recurses.
constexpr int kMaxDepth = 100;

/// "~" + "table" -> "~table"; "~table" + "size" -> "~table/size".
std::string memberName(const std::string& name, const std::string& key) {
  const std::string shown = shortenForMessage(key);
  if (name.empty() || name.back() == '~' || name.back() == '/') return name + shown;
  return name + "/" + shown;
}

const char* typeName(XmlRpc::XmlRpcValue::Type type) {
  switch (type) {
    case XmlRpc::XmlRpcValue::TypeDateTime:
      return "date-time";
    case XmlRpc::XmlRpcValue::TypeBase64:
      return "base64";
    case XmlRpc::XmlRpcValue::TypeInvalid:
      return "invalid";
    default:
      return "unknown";
  }
}

/// Converts `value`, which the caller owns: XmlRpcValue's casts are non-const.
Status convert(XmlRpc::XmlRpcValue& value, const std::string& name, int depth,
               ParameterValue* tree) {
  if (depth > kMaxDepth) {
    return Status::error("parameter " + shortenForMessage(name, 200) + " is nested more than " +
                         std::to_string(kMaxDepth) + " levels deep");
  }
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      *tree = ParameterValue::makeBool(static_cast<bool>(value));
      return Status::success();
    case XmlRpc::XmlRpcValue::TypeInt:
      *tree = ParameterValue::makeInt(static_cast<int>(value));
      return Status::success();
    case XmlRpc::XmlRpcValue::TypeDouble:
      *tree = ParameterValue::makeDouble(static_cast<double>(value));
      return Status::success();
    case XmlRpc::XmlRpcValue::TypeString:
      *tree = ParameterValue::makeString(static_cast<std::string&>(value));
      return Status::success();
    case XmlRpc::XmlRpcValue::TypeArray: {
      ParameterValue::List items;
      items.reserve(static_cast<std::size_t>(value.size()));
      for (int i = 0; i < value.size(); ++i) {
        ParameterValue item;
        if (Status status =
                convert(value[i], name + "[" + std::to_string(i) + "]", depth + 1, &item);
            !status) {
          return status;
        }
        items.push_back(std::move(item));
      }
      *tree = ParameterValue::makeList(std::move(items));
      return Status::success();
    }
    case XmlRpc::XmlRpcValue::TypeStruct: {
      ParameterValue map = ParameterValue::makeMap();
      for (auto& [key, member] : value) {
        ParameterValue converted;
        if (Status status = convert(member, memberName(name, key), depth + 1, &converted);
            !status) {
          return status;
        }
        map.set(key, std::move(converted));
      }
      *tree = std::move(map);
      return Status::success();
    }
    default:
      break;
  }
  return Status::error("parameter " + name + " has an unsupported type (" +
                       typeName(value.getType()) + ")");
}

}  // namespace

Status fromXmlRpc(const XmlRpc::XmlRpcValue& value, const std::string& name, ParameterValue* tree) {
  try {
    XmlRpc::XmlRpcValue copy = value;
    ParameterValue converted;
    if (Status status = convert(copy, name, 0, &converted); !status) return status;
    *tree = std::move(converted);
    return Status::success();
  } catch (const std::exception& e) {
    return Status::error("parameter " + name + " could not be converted: " + e.what());
  } catch (...) {  // XmlRpcException is no std::exception
    return Status::error("parameter " + name + " could not be converted");
  }
}

Status readPrivateParameters(const ros::NodeHandle& private_node_handle, ParameterValue* tree) {
  const std::string& ns = private_node_handle.getNamespace();
  XmlRpc::XmlRpcValue value;
  try {
    if (!private_node_handle.getParam(ns, value)) {
      *tree = ParameterValue::makeMap();
      return Status::success();
    }
  } catch (const std::exception& e) {
    return Status::error("cannot read the parameters under " + ns + ": " + e.what());
  } catch (...) {
    return Status::error("cannot read the parameters under " + ns);
  }
  ParameterValue converted;
  if (Status status = fromXmlRpc(value, "~", &converted); !status) return status;
  if (!converted.isMap()) {
    return Status::error("parameter " + ns + " is " + converted.describe() +
                         ", expected a namespace of parameters");
  }
  *tree = std::move(converted);
  return Status::success();
}

Status listFromString(const std::string& key, ParameterValue* parameters, std::string* note) {
  const ParameterValue* member = parameters->isMap() ? parameters->find(key) : nullptr;
  if (member == nullptr || !member->isString()) return Status::success();
  const std::string text = member->asString();
  const std::string how = ": set a list with rosparam set <node>/" + key +
                          " \"[a, b]\" or <rosparam param=\"" + key +
                          "\">[a, b]</rosparam> in a launch file";
  ParameterValue list = ParameterValue::makeList({ParameterValue::makeString(text)});
  const std::size_t first = text.find_first_not_of(" \t");
  if (first != std::string::npos && text[first] == '[') {
    ParameterValue parsed;
    const Status status = parseYamlParameters("value: " + text, "~" + key, &parsed);
    const ParameterValue* value = status ? parsed.find("value") : nullptr;
    bool strings = value != nullptr && value->isList();
    for (std::size_t i = 0; strings && i < value->list().size(); ++i)
      strings = value->list()[i].isString();
    if (!strings)
      return Status::error("parameter ~" + key + " = '" + shortenForMessage(text, 200) +
                           "' is no list of strings" + how);
    list = *value;
  }
  if (note != nullptr) {
    std::string items;
    for (const ParameterValue& item : list.list())
      items += (items.empty() ? "'" : ", '") + shortenForMessage(item.asString(), 200) + "'";
    *note = "parameter ~" + key + " is the string '" + shortenForMessage(text, 200) +
            "' (as rosrun's _" + key + ":= sets it): read as the list [" + items + "]";
  }
  parameters->set(key, std::move(list));
  return Status::success();
}

Status readStringList(const ros::NodeHandle& node_handle, const std::string& key,
                      std::vector<std::string>* list, std::string* note) {
  XmlRpc::XmlRpcValue value;
  try {
    if (!node_handle.getParam(key, value)) return Status::success();
  } catch (...) {
    return Status::error("cannot read parameter ~" + key);
  }
  ParameterValue tree = ParameterValue::makeMap();
  ParameterValue member;
  if (Status converted = fromXmlRpc(value, "~" + key, &member); !converted) return converted;
  tree.set(key, std::move(member));
  if (Status listed = listFromString(key, &tree, note); !listed) return listed;
  const ParameterValue& read = *tree.find(key);
  std::vector<std::string> strings;
  for (std::size_t i = 0; read.isList() && i < read.list().size(); ++i) {
    if (!read.list()[i].isString()) break;
    strings.push_back(read.list()[i].asString());
  }
  if (!read.isList() || strings.size() != read.list().size())
    return Status::error("parameter ~" + key + " is " + read.describe() +
                         ", expected a list of strings");
  *list = std::move(strings);
  return Status::success();
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
