// The simulator node: parameters -> options -> brick types -> SimNode -> spin
// with several threads (SimNode says which requests run where).
#include <malloc.h>

#include <memory>

#include <ros/package.h>
#include <ros/ros.h>

#include "brick_stack_sim/core/allocation_guard.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/ros/node.h"
#include "brick_stack_sim/ros/node_options.h"
#include "brick_stack_sim/ros/xmlrpc_parameters.h"

using namespace brick_stack_sim;

int main(int argc, char** argv) {
  // One malloc arena for every thread: a ~reset builds a world on one thread
  // while others answer clients, and with an arena per thread the freed
  // worlds' pages stayed spread over arenas that malloc_trim could not empty
  // (RSS grew by a reset's size every few cycles). The world is used under
  // one lock anyway, so the threads hardly contend for the arena.
  mallopt(M_ARENA_MAX, 1);
  ros::init(argc, argv, ros_adapter::kNodeName);
  ros::NodeHandle private_node_handle("~");
  ros_adapter::NodeOptions options;
  ParameterValue parameters;
  BrickTypeLibrary types;
  std::unique_ptr<ros_adapter::SimNode> node;
  Status status = ros_adapter::readPrivateParameters(private_node_handle, &parameters);
  // A list given on a rosrun line arrives as a string: read it as one.
  std::string list_note;
  if (status) status = ros_adapter::listFromString("scene_dirs", &parameters, &list_note);
  if (!list_note.empty()) ROS_INFO("%s", list_note.c_str());
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
  // Playing the parameter ~scene may run out of memory: a refusal like any other.
  if (status)
    status = refuseOnAllocationFailure("playing parameter ~scene", [&] {
      return ros_adapter::SimNode::create(private_node_handle, options, types, &node);
    });
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
