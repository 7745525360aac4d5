#include "brick_stack_sim/ros/xmlrpc_parameters.h"

#include <exception>
#include <utility>

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

}  // namespace ros_adapter
}  // namespace brick_stack_sim
