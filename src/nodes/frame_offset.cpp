// frame_offset: latches one fixed transform on /tf_static, parent -> child,
// a translation [m] and a yaw [rad]. compare.launch places each simulator's
// fixed frame with it; Debian's tf2_ros ships no static_transform_publisher.
#include <cmath>
#include <string>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "frame_offset");
  ros::NodeHandle private_nh("~");
  geometry_msgs::TransformStamped transform;
  private_nh.param<std::string>("parent", transform.header.frame_id, "world");
  private_nh.param<std::string>("child", transform.child_frame_id, "");
  double x = 0.0, y = 0.0, z = 0.0, yaw = 0.0;
  private_nh.param("x", x, x);
  private_nh.param("y", y, y);
  private_nh.param("z", z, z);
  private_nh.param("yaw", yaw, yaw);
  if (transform.child_frame_id.empty() || transform.header.frame_id.empty() ||
      transform.child_frame_id == transform.header.frame_id || !std::isfinite(x) ||
      !std::isfinite(y) || !std::isfinite(z) || !std::isfinite(yaw)) {
    ROS_FATAL(
        "frame_offset: ~parent and ~child must be two different frames and ~x, ~y, ~z, "
        "~yaw finite");
    return 2;
  }
  transform.header.stamp = ros::Time::now();
  transform.transform.translation.x = x;
  transform.transform.translation.y = y;
  transform.transform.translation.z = z;
  transform.transform.rotation.z = std::sin(yaw / 2);
  transform.transform.rotation.w = std::cos(yaw / 2);
  tf2_ros::StaticTransformBroadcaster broadcaster;
  broadcaster.sendTransform(transform);
  ros::spin();
  return 0;
}
