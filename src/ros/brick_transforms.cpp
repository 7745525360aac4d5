#include "brick_stack_sim/ros/brick_transforms.h"

#include <algorithm>

#include <tf2_msgs/TFMessage.h>

#include "brick_stack_sim/core/simulation/simulation_config.h"
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

FrameNames::FrameNames(const std::string& frame_id, const std::string& frame_prefix)
    : fixed_(frame_id), prefix_(frame_prefix), table_(prefixedFrame(frame_prefix, "table")) {}

std::string FrameNames::brick(const std::string& id) const { return prefixedFrame(prefix_, id); }

Status FrameNames::checkBrickId(const std::string& id) const {
  if (id.empty() || brick(id) != fixed_) return Status::success();
  return Status::error("id '" + id + "' would name the tf frame '" + fixed_ +
                       "', the fixed frame (~frame_id) itself: choose another id, or set "
                       "~frame_prefix");
}

BrickTransforms::BrickTransforms(ros::NodeHandle& node_handle, const FrameNames& names,
                                 double static_period)
    : names_(names), static_period_(static_period) {
  // Global names, as tf2_ros's broadcasters use, whatever the node's namespace.
  tf_publisher_ = node_handle.advertise<tf2_msgs::TFMessage>("/tf", 100);
  static_publisher_ = node_handle.advertise<tf2_msgs::TFMessage>("/tf_static", 1, true);
}

void BrickTransforms::publish(const BrickMirror& mirror, const BrickMirror::Changes& changes,
                              const ros::Time& stamp, int* skipped) {
  const std::vector<MirroredBrick>& bricks = mirror.bricks();
  if (changes.replaced) {
    moving_.clear();
    static_due_ = true;
  }
  for (const RemovedBrick& gone : changes.removed) {
    // Gone while at rest: the static set must lose it.
    if (moving_.erase(gone.serial) == 0) static_due_ = true;
  }
  tf2_msgs::TFMessage moved;
  std::map<unsigned, Moving> still_moving;
  auto send = [&](const MirroredBrick& brick) {
    const BrickSnapshot& snapshot = brick.snapshot;
    const auto before = moving_.find(snapshot.serial);
    if (before == moving_.end()) {
      static_due_ = true;  // it leaves the static set (or was never in it)
    } else if (before->second.stamp == stamp) {
      Moving& waiting = still_moving[snapshot.serial] = before->second;
      waiting.pending = true;
      return;
    }
    moved.transforms.push_back(
        stamped(names_.fixed(), names_.brick(snapshot.id), toTransformMsg(snapshot.pose), stamp));
    still_moving[snapshot.serial] = Moving{snapshot.pose, stamp, false};
  };
  for (std::size_t index : changes.moved) {
    const MirroredBrick& brick = bricks[index];
    if (!brick.snapshot.pose.matrix().allFinite()) {
      ++*skipped;
      continue;
    }
    send(brick);
  }
  // A brick that waited for a new stamp goes now, unless it moved again
  // (then it was sent above).
  for (const auto& [serial, entry] : moving_) {
    if (!entry.pending || still_moving.count(serial)) continue;
    const auto found = std::lower_bound(
        bricks.begin(), bricks.end(), serial,
        [](const MirroredBrick& brick, unsigned s) { return brick.snapshot.serial < s; });
    if (found != bricks.end() && found->snapshot.serial == serial &&
        found->snapshot.pose.matrix().allFinite())
      send(*found);
  }
  // What was on /tf and did not move for a publish is at rest.
  for (const auto& [serial, entry] : moving_)
    if (!still_moving.count(serial)) static_due_ = true;
  moving_ = std::move(still_moving);
  if (!moved.transforms.empty() && tf_publisher_.getNumSubscribers() > 0)
    tf_publisher_.publish(moved);
  if (static_due_ && ros::WallTime::now() >= last_static_ + static_period_)
    publishStatic(mirror, stamp);
}

void BrickTransforms::clear(const ros::Time& stamp) {
  moving_.clear();
  publishStatic(BrickMirror(), stamp);
}

void BrickTransforms::publishStatic(const BrickMirror& mirror, const ros::Time& stamp) {
  static_due_ = false;
  last_static_ = ros::WallTime::now();
  tf2_msgs::TFMessage all;
  // The table top's centre is the fixed frame's origin.
  all.transforms.push_back(stamped(names_.fixed(), names_.table(),
                                   toTransformMsg(Eigen::Isometry3d::Identity()), stamp));
  // Stamped now, not when they came to rest: a listener that holds such a
  // frame as a moving one may then look it up until now.
  for (const MirroredBrick& brick : mirror.bricks())
    if (!moving_.count(brick.snapshot.serial) && brick.snapshot.pose.matrix().allFinite())
      all.transforms.push_back(stamped(names_.fixed(), names_.brick(brick.snapshot.id),
                                       toTransformMsg(brick.snapshot.pose), stamp));
  static_publisher_.publish(all);
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
