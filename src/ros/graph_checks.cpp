#include "brick_stack_sim/ros/graph_checks.h"

#include <functional>
#include <sstream>

namespace brick_stack_sim {
namespace ros_adapter {

GraphChecks::GraphChecks(ros::NodeHandle& node_handle, const std::string& table_frame,
                         bool publishes_clock, const Windows& windows)
    : table_frame_(table_frame), own_name_(ros::this_node::getName()), clock_wait_(windows.clock) {
  using Event = ros::MessageEvent<const tf2_msgs::TFMessage>;
  // Global names, as the node publishes them. The latched /tf_static of a
  // simulator that started first arrives at once; /tf while its bricks move.
  tf_subscriber_ = node_handle.subscribe<tf2_msgs::TFMessage>(
      "/tf", 100,
      boost::function<void(const Event&)>([this](const Event& e) { onTransforms("/tf", e); }));
  tf_static_subscriber_ = node_handle.subscribe<tf2_msgs::TFMessage>(
      "/tf_static", 10, boost::function<void(const Event&)>([this](const Event& e) {
        onTransforms("/tf_static", e);
      }));
  clash_timer_ = node_handle.createWallTimer(ros::WallDuration(windows.clash),
                                             &GraphChecks::endClashWindow, this, true);
  if (ros::Time::isSimTime() && !publishes_clock) {
    clock_subscriber_ = node_handle.subscribe("/clock", 1, &GraphChecks::onClock, this);
    clock_timer_ = node_handle.createWallTimer(ros::WallDuration(windows.clock),
                                               &GraphChecks::endClockWindow, this, true);
  }
}

std::string GraphChecks::clashWarning(const std::string& table_frame, const std::string& topic,
                                      const std::string& publisher) {
  std::ostringstream text;
  text << "another node, " << publisher << ", sends the frame '" << table_frame << "' on " << topic
       << " as this node does: the two overwrite each other's frames on tf (two simulators "
          "without a prefix?); give each its own ~frame_prefix (sim.launch frame_prefix:=sim1)";
  return text.str();
}

std::string GraphChecks::clockWarning(double waited) {
  std::ostringstream text;
  text << "/use_sim_time is true but no /clock arrived within " << waited
       << " s and this node does not publish it (publish_clock is false): every stamp stays 0 "
          "and sim-time timers never fire; set publish_clock:=true (sim.launch "
          "publish_clock:=true) or start a node that publishes /clock";
  return text.str();
}

void GraphChecks::onTransforms(const std::string& topic,
                               const ros::MessageEvent<const tf2_msgs::TFMessage>& event) {
  const std::string& publisher = event.getPublisherName();
  if (publisher == own_name_) return;  // this node's own, delivered within the process
  for (const auto& transform : event.getConstMessage()->transforms) {
    if (transform.child_frame_id != table_frame_) continue;
    if (clash_warned_.exchange(true)) return;
    ROS_WARN("%s", clashWarning(table_frame_, topic, publisher).c_str());
    return;
  }
}

void GraphChecks::endClashWindow(const ros::WallTimerEvent& /*event*/) {
  tf_subscriber_.shutdown();
  tf_static_subscriber_.shutdown();
}

void GraphChecks::onClock(const rosgraph_msgs::Clock::ConstPtr& /*clock*/) { clock_seen_ = true; }

void GraphChecks::endClockWindow(const ros::WallTimerEvent& /*event*/) {
  clock_subscriber_.shutdown();
  // roscpp's own clock counts too: one that arrived before this subscriber.
  if (!clock_seen_ && ros::Time::now().isZero()) ROS_WARN("%s", clockWarning(clock_wait_).c_str());
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
