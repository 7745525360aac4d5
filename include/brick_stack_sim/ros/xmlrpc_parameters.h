#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// An XML-RPC value of the parameter server as a parameter tree, so that the node reads its
/// options with the same core readers as the batch runner: boolean, int, double, string, array,
/// struct map one to one; any other type (date-time, base64, invalid) is an error naming `name`
/// ("parameter ~stamp has an unsupported type (date-time)"). `name` is the value's path, used in
/// messages; members are named "<name>/<key>" ("~" + key below "~") and items "<name>[<i>]".
/// Nesting deeper than 100 levels is an error. `*tree` is set only on success.
Status fromXmlRpc(const XmlRpc::XmlRpcValue& value, const std::string& name, ParameterValue* tree);

/// Every parameter under the node's private namespace as one tree (an empty map when it has none):
/// the node reads its options from this, so that a parameter it does not know is found. A private
/// namespace holding a single value instead of parameters is an error. Needs a running master.
Status readPrivateParameters(const ros::NodeHandle& private_node_handle, ParameterValue* tree);

/// A list of strings given on a rosrun line arrives as a string: roscpp
/// stores `_scene_dirs:=[a, b]` as the text "[a, b]", and `_scene_dirs:=a` as
/// "a", and the master keeps it for the next start. So a string member `key`
/// of the map `parameters` is taken as a list: a YAML flow list ("[a, b]") as
/// its items, any other string as a list of that one string; `*note` (if
/// given) then says so, for the log. A member that is missing or not a string
/// is left alone. A "[...]" that is no list of strings is refused with a
/// message naming ~key and how to set it.
Status listFromString(const std::string& key, ParameterValue* parameters,
                      std::string* note = nullptr);

/// Reads the list of strings `key` from `node_handle`, accepting a string as
/// listFromString does; `*list` is unchanged when it is not set. Any other
/// type is refused, naming ~key.
Status readStringList(const ros::NodeHandle& node_handle, const std::string& key,
                      std::vector<std::string>* list, std::string* note = nullptr);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
