#pragma once
// Two mistakes of the graph around the node that nothing else reports, each
// warned of once, in the first seconds after the node's start and off the
// step path (docs/ros_interface.md, "Frames and units"):
// - another node sends the node's table frame on /tf or /tf_static: two
//   simulators without ~frame_prefix overwrite each other's frames;
// - /use_sim_time is set, the node does not publish /clock and no /clock
//   arrives: every stamp of the graph stays 0.

#include <atomic>
#include <string>

#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_msgs/TFMessage.h>

namespace brick_stack_sim {
namespace ros_adapter {

class GraphChecks {
 public:
  /// How long the checks listen [s of wall time].
  struct Windows {
    double clash = 5.0;  ///< /tf and /tf_static, for another publisher of the table frame.
    double clock = 1.0;  ///< /clock, for a first message, with /use_sim_time.
  };

  /// Subscribes on `node_handle` for the windows' time: /tf and /tf_static
  /// always, /clock when /use_sim_time is set and `publishes_clock` is not.
  GraphChecks(ros::NodeHandle& node_handle, const std::string& table_frame, bool publishes_clock,
              const Windows& windows);

  /// The warning of a clash with `publisher` on `topic`, and of a missing
  /// /clock: the texts the checks log (tested without a master).
  static std::string clashWarning(const std::string& table_frame, const std::string& topic,
                                  const std::string& publisher);
  static std::string clockWarning(double waited);

 private:
  void onTransforms(const std::string& topic,
                    const ros::MessageEvent<const tf2_msgs::TFMessage>& event);
  void endClashWindow(const ros::WallTimerEvent& event);
  void onClock(const rosgraph_msgs::Clock::ConstPtr& clock);
  void endClockWindow(const ros::WallTimerEvent& event);

  std::string table_frame_;
  std::string own_name_;
  double clock_wait_;
  // Flags, not a mutex: a subscriber's shutdown() waits for its running
  // callback, which must then not wait for the caller.
  std::atomic<bool> clash_warned_{false};
  std::atomic<bool> clock_seen_{false};
  ros::Subscriber tf_subscriber_;
  ros::Subscriber tf_static_subscriber_;
  ros::Subscriber clock_subscriber_;
  ros::WallTimer clash_timer_;
  ros::WallTimer clock_timer_;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
