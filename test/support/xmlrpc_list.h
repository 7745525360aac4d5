#pragma once
// An XML-RPC array from a brace list, as the parameter server holds lists.

#include <initializer_list>

#include <xmlrpcpp/XmlRpcValue.h>

namespace brick_stack_sim {
namespace test {

inline XmlRpc::XmlRpcValue xmlRpcList(std::initializer_list<XmlRpc::XmlRpcValue> items) {
  XmlRpc::XmlRpcValue value;
  value.setSize(static_cast<int>(items.size()));
  int i = 0;
  for (const XmlRpc::XmlRpcValue& item : items) value[i++] = item;
  return value;
}

}  // namespace test
}  // namespace brick_stack_sim
