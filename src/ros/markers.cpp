#include "brick_stack_sim/ros/markers.h"

#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

std_msgs::ColorRGBA rgb(float r, float g, float b) {
  std_msgs::ColorRGBA color;
  color.r = r;
  color.g = g;
  color.b = b;
  color.a = 1.0f;
  return color;
}

}  // namespace

BrickLook brickLook(const BrickSnapshot& brick) {
  if (brick.fell_off) return BrickLook::kFellOff;
  switch (brick.state) {
    case BrickState::kHeld:
      return BrickLook::kHeld;
    case BrickState::kLeaning:
      return BrickLook::kLeaning;
    case BrickState::kStable:
      return BrickLook::kStable;
    case BrickState::kDynamic:
      break;
  }
  return brick.asleep ? BrickLook::kAsleep : BrickLook::kDynamic;
}

std_msgs::ColorRGBA brickColor(BrickLook look) {
  switch (look) {
    case BrickLook::kFellOff:
      return rgb(0.85f, 0.10f, 0.10f);  // red
    case BrickLook::kHeld:
      return rgb(0.60f, 0.25f, 0.85f);  // violet
    case BrickLook::kLeaning:
      return rgb(1.00f, 0.60f, 0.00f);  // orange
    case BrickLook::kStable:
      return rgb(0.15f, 0.70f, 0.25f);  // green
    case BrickLook::kAsleep:
      return rgb(0.45f, 0.55f, 0.75f);  // grey-blue
    case BrickLook::kDynamic:
      return rgb(0.90f, 0.78f, 0.55f);  // pine
  }
  return rgb(1.0f, 1.0f, 1.0f);
}

int brickMarkerId(const BrickSnapshot& brick) { return static_cast<int>(brick.serial); }

visualization_msgs::MarkerArray makeBrickMarkers(const std::vector<BrickSnapshot>& bricks,
                                                 const std::string& frame_id,
                                                 const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  array.markers.reserve(bricks.size() + 1);
  visualization_msgs::Marker clear;
  clear.header.frame_id = frame_id;
  clear.header.stamp = stamp;
  clear.ns = kBrickMarkerNamespace;
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);

  for (const BrickSnapshot& brick : bricks) {
    if (!allFinite(brick.pose) || !brick.size.allFinite()) continue;
    visualization_msgs::Marker marker;
    marker.header.frame_id = frame_id;
    marker.header.stamp = stamp;
    marker.ns = kBrickMarkerNamespace;
    marker.id = brickMarkerId(brick);
    marker.type = visualization_msgs::Marker::CUBE;
    marker.action = visualization_msgs::Marker::ADD;
    marker.pose = toPoseMsg(brick.pose);
    marker.scale = toVectorMsg(brick.size);
    marker.color = brickColor(brickLook(brick));
    marker.frame_locked = false;
    array.markers.push_back(marker);
  }
  return array;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
