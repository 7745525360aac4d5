#pragma once
// The bricks' tf frames at a cost that follows what moves. A brick whose pose
// changed since it was last sent goes on /tf at every publish; one that has
// not changed for a publish is at rest, and joins the table on a latched
// /tf_static, so that a listener that connects later still finds every frame.
// The static set is sent again when it changes, at most once per
// `static_period` of wall time: a brick that came to rest was last sent on
// /tf at its resting pose already, so only late listeners wait for it.

#include <string>
#include <vector>

#include <ros/ros.h>
#include <Eigen/Geometry>

#include "brick_stack_sim/core/brick.h"

namespace brick_stack_sim {
namespace ros_adapter {

class BrickTransforms {
 public:
  /// `frame_id`: the fixed frame; `frame_prefix` goes before every brick id
  /// and "table". Advertises /tf and a latched /tf_static on `node_handle`.
  BrickTransforms(ros::NodeHandle& node_handle, const std::string& frame_id,
                  const std::string& frame_prefix, double static_period);

  /// Sends what moved on /tf, stamped `stamp`, and the static set when due.
  /// `bricks` in placement order (rising serials), as BrickWorld::poses()
  /// gives them. A pose that is not finite is left out (counted in `skipped`).
  void publish(const std::vector<BrickPose>& bricks, const ros::Time& stamp, int* skipped);

  /// Forgets every brick and sends the table alone on /tf_static: the
  /// node's first call, before any brick exists.
  void clear(const ros::Time& stamp);

 private:
  struct Sent {
    std::string id;
    unsigned serial = 0;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    ros::Time stamp;       ///< Of its last /tf message.
    bool resting = false;  ///< On /tf_static.
  };
  void publishStatic(const ros::Time& stamp);

  std::string frame_id_;
  std::string frame_prefix_;
  ros::WallDuration static_period_;
  ros::Publisher tf_publisher_;
  ros::Publisher static_publisher_;
  /// In placement order: each publish walks it beside the world's bricks,
  /// without a lookup by id.
  std::vector<Sent> sent_;
  bool static_due_ = true;  ///< The static set changed since it was last sent.
  ros::WallTime last_static_;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
