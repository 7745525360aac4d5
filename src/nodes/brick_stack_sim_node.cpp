// The simulator node: parameters -> options -> brick types -> SimNode -> spin.
#include <memory>

#include <ros/package.h>
#include <ros/ros.h>

#include "brick_stack_sim/core/brick_type.h"
#include "brick_stack_sim/ros/node.h"
#include "brick_stack_sim/ros/node_options.h"

using namespace brick_stack_sim;

int main(int argc, char** argv) {
  ros::init(argc, argv, "brick_sim");
  ros::NodeHandle private_node_handle("~");
  ros_adapter::NodeOptions options;
  BrickTypeLibrary types;
  std::unique_ptr<ros_adapter::SimNode> node;
  Status status =
      ros_adapter::loadNodeOptions(ros_adapter::RosParameterReader(private_node_handle), &options);
  if (status)
    status = ros_adapter::resolveDataPaths(ros::package::getPath("brick_stack_sim"), &options);
  if (status) {
    status = BrickTypeLibrary::load(options.types_urdf, options.materials_yaml, &types);
    if (!status)
      status.message = "brick types from ~types_urdf = '" + options.types_urdf +
                       "', ~materials_yaml = '" + options.materials_yaml + "': " + status.message;
  }
  if (status) status = ros_adapter::SimNode::create(private_node_handle, options, types, &node);
  if (!status) {
    ROS_FATAL("brick_sim cannot start: %s", status.message.c_str());
    return 1;
  }
  ros::spin();
  return 0;
}
