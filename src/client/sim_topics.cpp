// SimClient's topics: the subscribe helpers and ~held_target.
#include <ros/time.h>

#include "brick_stack_sim/client/sim_client.h"

namespace brick_stack_sim {
namespace client {

ros::Subscriber SimClient::subscribeBricks(const BricksCallback& callback,
                                           std::uint32_t queue_size) {
  return node_handle_.subscribe<BrickArray>(resolve(ros_adapter::kBricksTopic), queue_size,
                                            callback);
}

ros::Subscriber SimClient::subscribeEvents(const EventsCallback& callback,
                                           std::uint32_t queue_size) {
  return node_handle_.subscribe<StabilityEvent>(resolve(ros_adapter::kEventsTopic), queue_size,
                                                callback);
}

ros::Subscriber SimClient::subscribeMarkers(const MarkersCallback& callback,
                                            std::uint32_t queue_size) {
  return node_handle_.subscribe<visualization_msgs::MarkerArray>(
      resolve(ros_adapter::kMarkersTopic), queue_size, callback);
}

ros::Subscriber SimClient::subscribeClock(const ClockCallback& callback, std::uint32_t queue_size) {
  return node_handle_.subscribe<rosgraph_msgs::Clock>(resolve(ros_adapter::kClockTopic), queue_size,
                                                      callback);
}

const ros::Publisher& SimClient::advertiseHeldTarget(std::uint32_t queue_size) {
  if (!held_target_)
    held_target_ = node_handle_.advertise<geometry_msgs::PoseStamped>(
        resolve(ros_adapter::kHeldTargetTopic), queue_size);
  return held_target_;
}

void SimClient::publishHeldTarget(const geometry_msgs::Pose& pose) {
  geometry_msgs::PoseStamped target;
  target.header.stamp = ros::Time::now();
  target.header.frame_id = ros_adapter::kWorldFrame;
  target.pose = pose;
  publishHeldTarget(target);
}

void SimClient::publishHeldTarget(const geometry_msgs::PoseStamped& target) {
  advertiseHeldTarget().publish(target);
}

}  // namespace client
}  // namespace brick_stack_sim
