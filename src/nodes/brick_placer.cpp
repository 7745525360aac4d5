// The RViz brick placer: parameters -> options -> brick types -> BrickPlacer -> spin.
#include <ros/ros.h>

#include "brick_stack_sim/ros/xmlrpc_parameters.h"
#include "brick_stack_sim/teleop/brick_placer.h"
#include "brick_stack_sim/teleop/teleop_options.h"

using namespace brick_stack_sim;

int main(int argc, char** argv) {
  ros::init(argc, argv, "brick_placer");
  // Held for the whole run: roscpp shuts the node (and its logging) down
  // when the last NodeHandle goes away.
  ros::NodeHandle private_node_handle("~");
  ParameterValue parameters;
  teleop::PlacerOptions options;
  BrickTypeLibrary types;
  Status status = ros_adapter::readPrivateParameters(private_node_handle, &parameters);
  if (status) status = teleop::loadPlacerOptions(parameters, &options);
  if (status) status = teleop::loadPlacerTypes(options, &types);
  if (!status) {
    ROS_FATAL("brick_placer cannot start: %s", status.message.c_str());
    return 1;
  }
  teleop::BrickPlacer placer(options, types);
  placer.waitForSimulator();
  ros::spin();
  return 0;
}
