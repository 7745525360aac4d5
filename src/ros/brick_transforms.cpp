#include "brick_stack_sim/ros/brick_transforms.h"

#include <tf2_msgs/TFMessage.h>

#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

geometry_msgs::TransformStamped stamped(const std::string& parent, const std::string& child,
                                        const geometry_msgs::Transform& transform,
                                        const ros::Time& stamp) {
  geometry_msgs::TransformStamped result;
  result.header.stamp = stamp;
  result.header.frame_id = parent;
  result.child_frame_id = child;
  result.transform = transform;
  return result;
}

}  // namespace

BrickTransforms::BrickTransforms(ros::NodeHandle& node_handle, const std::string& frame_id,
                                 const std::string& frame_prefix, double static_period)
    : frame_id_(frame_id), frame_prefix_(frame_prefix), static_period_(static_period) {
  // Global names, as tf2_ros's broadcasters use, whatever the node's namespace.
  tf_publisher_ = node_handle.advertise<tf2_msgs::TFMessage>("/tf", 100);
  static_publisher_ = node_handle.advertise<tf2_msgs::TFMessage>("/tf_static", 1, true);
}

void BrickTransforms::publish(const std::vector<BrickPose>& bricks, const ros::Time& stamp,
                              int* skipped) {
  tf2_msgs::TFMessage moved;
  std::vector<Sent> next;
  next.reserve(bricks.size());
  // Both lists rise in serial: one walk pairs each brick with what was sent
  // of it. Serials start again after a reset, so the id must match too.
  std::size_t old = 0;
  for (const BrickPose& brick : bricks) {
    while (old < sent_.size() && sent_[old].serial < brick.serial) {
      static_due_ = static_due_ || sent_[old].resting;  // removed while at rest
      ++old;
    }
    Sent* before = nullptr;
    if (old < sent_.size() && sent_[old].serial == brick.serial) {
      if (sent_[old].id == brick.id) {
        before = &sent_[old];
      } else {
        static_due_ = static_due_ || sent_[old].resting;
      }
      ++old;
    }
    if (!brick.pose.matrix().allFinite()) {
      ++*skipped;
      if (before) static_due_ = static_due_ || before->resting;
      continue;
    }
    if (before && before->pose.matrix() == brick.pose.matrix()) {
      // Unchanged for a publish: at rest, on /tf_static from now on.
      if (!before->resting) before->resting = static_due_ = true;
      next.push_back(std::move(*before));
      continue;
    }
    // tf2 warns of a second message for a frame at one stamp (paused on sim
    // time): such a change waits for the next stamp.
    if (before && before->stamp == stamp) {
      next.push_back(std::move(*before));
      continue;
    }
    if (before && before->resting) static_due_ = true;
    moved.transforms.push_back(
        stamped(frame_id_, frame_prefix_ + brick.id, toTransformMsg(brick.pose), stamp));
    next.push_back(Sent{brick.id, brick.serial, brick.pose, stamp, false});
  }
  for (; old < sent_.size(); ++old) static_due_ = static_due_ || sent_[old].resting;
  sent_ = std::move(next);
  if (!moved.transforms.empty() && tf_publisher_.getNumSubscribers() > 0)
    tf_publisher_.publish(moved);
  if (static_due_ && ros::WallTime::now() >= last_static_ + static_period_) publishStatic(stamp);
}

void BrickTransforms::clear(const ros::Time& stamp) {
  sent_.clear();
  publishStatic(stamp);
}

void BrickTransforms::publishStatic(const ros::Time& stamp) {
  static_due_ = false;
  last_static_ = ros::WallTime::now();
  tf2_msgs::TFMessage all;
  // The table top's centre is the fixed frame's origin.
  all.transforms.push_back(stamped(frame_id_, frame_prefix_ + "table",
                                   toTransformMsg(Eigen::Isometry3d::Identity()), stamp));
  // Stamped now, not when they came to rest: a listener that holds such a
  // frame as a moving one may then look it up until now.
  for (const Sent& entry : sent_)
    if (entry.resting)
      all.transforms.push_back(
          stamped(frame_id_, frame_prefix_ + entry.id, toTransformMsg(entry.pose), stamp));
  static_publisher_.publish(all);
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
