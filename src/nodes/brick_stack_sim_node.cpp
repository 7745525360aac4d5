// The simulator node: parameters -> options -> brick types -> SimNode -> spin
// with several threads (SimNode says which requests run where).
#include <memory>

#include <ros/package.h>
#include <ros/ros.h>

#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/ros/node.h"
#include "brick_stack_sim/ros/node_options.h"
#include "brick_stack_sim/ros/xmlrpc_parameters.h"

using namespace brick_stack_sim;

int main(int argc, char** argv) {
  ros::init(argc, argv, ros_adapter::kNodeName);
  ros::NodeHandle private_node_handle("~");
  ros_adapter::NodeOptions options;
  ParameterValue parameters;
  BrickTypeLibrary types;
  std::unique_ptr<ros_adapter::SimNode> node;
  Status status = ros_adapter::readPrivateParameters(private_node_handle, &parameters);
  if (status) status = ros_adapter::loadNodeOptions(parameters, &options);
  if (status)
    status = ros_adapter::resolveDataPaths(ros::package::getPath("brick_stack_sim"), &options);
  const DataOptions& data = options.config.data;
  if (status) {
    status = BrickTypeLibrary::load(data.types_urdf, data.materials_yaml, &types);
    if (!status)
      status.message = "brick types from ~types_urdf = '" + data.types_urdf +
                       "', ~materials_yaml = '" + data.materials_yaml + "': " + status.message;
  }
  if (status) status = ros_adapter::SimNode::create(private_node_handle, options, types, &node);
  if (!status) {
    ROS_FATAL("brick_sim cannot start: %s", status.message.c_str());
    return 1;
  }
  // Declared after the node: stopped before it goes away.
  ros::AsyncSpinner spinner(ros_adapter::kServiceThreads);
  spinner.start();
  ros::waitForShutdown();
  spinner.stop();
  return 0;
}
