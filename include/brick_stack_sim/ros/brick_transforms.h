#pragma once
// The bricks' tf frames at a cost that follows what moves. A brick whose pose
// changed since it was last sent goes on /tf at every publish; one that has
// not changed for a publish is at rest, and joins the table on a latched
// /tf_static, so that a listener that connects later still finds every frame.
// The static set is sent again when it changes, at most once per
// `static_period` of wall time: a brick that came to rest was last sent on
// /tf at its resting pose already, so only late listeners wait for it. Each
// send is the whole current set, so the latched message loses a removed
// brick (docs/ros_interface.md, "Topics").

#include <map>
#include <string>

#include <ros/ros.h>
#include <Eigen/Geometry>

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/ros/brick_mirror.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// The frames the node names on tf (docs/ros_interface.md, "Frames and
/// units"): `<frame_prefix>/<id>` per brick and `<frame_prefix>/table`, each
/// a child of the fixed frame `frame_id` (prefixedFrame joins them).
class FrameNames {
 public:
  FrameNames(const std::string& frame_id, const std::string& frame_prefix);
  const std::string& fixed() const { return fixed_; }
  const std::string& table() const { return table_; }
  std::string brick(const std::string& id) const;
  /// Refuses a brick id whose frame would be the fixed frame itself (tf2's
  /// TF_SELF_TRANSFORM), naming both.
  Status checkBrickId(const std::string& id) const;

 private:
  std::string fixed_;
  std::string prefix_;
  std::string table_;
};

class BrickTransforms {
 public:
  /// `names`: the fixed frame and the frames of the bricks and the table.
  /// Advertises /tf and a latched /tf_static on `node_handle`.
  BrickTransforms(ros::NodeHandle& node_handle, const FrameNames& names, double static_period);

  /// Sends the bricks that moved on /tf, stamped `stamp`, and the static
  /// set (every other finite brick of `mirror`) when due. `changes`: what
  /// the mirror's last update found. A brick that moved to a pose that is
  /// not finite is left out (counted in `skipped`).
  void publish(const BrickMirror& mirror, const BrickMirror::Changes& changes,
               const ros::Time& stamp, int* skipped);

  /// Forgets every brick and sends the table alone on /tf_static: the
  /// node's first call, before any brick exists.
  void clear(const ros::Time& stamp);

 private:
  /// A brick sent on /tf at the last publish, or waiting to be.
  struct Moving {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< Last sent on /tf.
    ros::Time stamp;                                         ///< Of that message.
    /// It moved again within one stamp (paused on sim time), where tf2
    /// warns of a second message: sent at the next stamp.
    bool pending = false;
  };
  void publishStatic(const BrickMirror& mirror, const ros::Time& stamp);

  FrameNames names_;
  ros::WallDuration static_period_;
  ros::Publisher tf_publisher_;
  ros::Publisher static_publisher_;
  /// By serial: the bricks on /tf, which are not in the static set; few
  /// in a settled scene, so a publish costs what moved.
  std::map<unsigned, Moving> moving_;
  bool static_due_ = true;  ///< The static set changed since it was last sent.
  ros::WallTime last_static_;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
