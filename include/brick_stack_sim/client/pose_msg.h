#pragma once
// A pose message from a position and a turn about z: what planners, the
// benchmark and the tests send as a brick's pose.

#include <cmath>

#include <geometry_msgs/Pose.h>

namespace brick_stack_sim {
namespace client {

/// The pose at (x, y, z) [m], turned by `yaw` [rad] about z.
inline geometry_msgs::Pose poseAt(double x, double y, double z, double yaw = 0.0) {
  geometry_msgs::Pose pose;
  pose.position.x = x;
  pose.position.y = y;
  pose.position.z = z;
  pose.orientation.z = std::sin(yaw / 2);
  pose.orientation.w = std::cos(yaw / 2);
  return pose;
}

}  // namespace client
}  // namespace brick_stack_sim
