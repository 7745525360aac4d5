#include "brick_stack_sim/teleop/sim_client.h"

#include <algorithm>

#include <geometry_msgs/PoseStamped.h>

#include "brick_stack_sim/GetBricks.h"
#include "brick_stack_sim/GraspBrick.h"
#include "brick_stack_sim/PlaceBrick.h"
#include "brick_stack_sim/ReleaseBrick.h"
#include "brick_stack_sim/teleop/placement_geometry.h"

namespace brick_stack_sim {
namespace teleop {

namespace {

/// How long one call waits for its service [s]: long enough to ride out a
/// simulator that is just starting, short enough that a click in RViz on a
/// dead simulator answers at once with a warning.
constexpr double kCallWait = 1.0;

}  // namespace

SimClient::SimClient(ros::NodeHandle node_handle, const std::string& sim_namespace)
    : sim_namespace_(sim_namespace), node_handle_(node_handle) {
  get_bricks_ = node_handle_.serviceClient<GetBricks>(sim_namespace_ + "/get_bricks");
  place_brick_ = node_handle_.serviceClient<PlaceBrick>(sim_namespace_ + "/place_brick");
  grasp_brick_ = node_handle_.serviceClient<GraspBrick>(sim_namespace_ + "/grasp_brick");
  release_brick_ = node_handle_.serviceClient<ReleaseBrick>(sim_namespace_ + "/release_brick");
  held_target_ =
      node_handle_.advertise<geometry_msgs::PoseStamped>(sim_namespace_ + "/held_target", 10);
}

bool SimClient::waitForSimulator(double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
  for (ros::ServiceClient* client : {&get_bricks_, &place_brick_}) {
    const double left = std::max(0.0, (end - ros::WallTime::now()).toSec());
    if (!client->waitForExistence(ros::Duration(left))) {
      ROS_WARN(
          "no simulator: %s did not come up within %g s (parameter ~sim = '%s'); every action "
          "will say so until it does",
          client->getService().c_str(), timeout, sim_namespace_.c_str());
      return false;
    }
  }
  ROS_INFO("simulator found at %s", sim_namespace_.c_str());
  return true;
}

template <typename Service>
bool SimClient::call(ros::ServiceClient& client, Service& service) {
  const std::string& name = client.getService();
  if (!client.waitForExistence(ros::Duration(kCallWait))) {
    ROS_WARN("%s is not available: is the simulator running at %s (parameter ~sim)?", name.c_str(),
             sim_namespace_.c_str());
    return false;
  }
  if (!client.call(service)) {
    ROS_WARN("call to %s failed (the simulator went away?)", name.c_str());
    return false;
  }
  if (!service.response.success) {
    ROS_WARN("%s refused: %s", name.c_str(), service.response.message.c_str());
    return false;
  }
  return true;
}

bool SimClient::getBricks(std::vector<Brick>* bricks) {
  GetBricks service;
  if (!call(get_bricks_, service)) return false;
  *bricks = std::move(service.response.bricks);
  return true;
}

bool SimClient::placeBrick(const std::string& type, const geometry_msgs::Pose& pose,
                           std::string* id) {
  PlaceBrick service;
  service.request.type = type;
  service.request.pose = pose;
  if (!call(place_brick_, service)) return false;
  *id = service.response.id;
  return true;
}

bool SimClient::graspBrick(const std::string& id) {
  GraspBrick service;
  service.request.id = id;
  if (!call(grasp_brick_, service)) return false;
  held_ = id;
  return true;
}

std::optional<Brick> SimClient::graspNearest(const Eigen::Vector3d& point,
                                             const std::string& action) {
  std::vector<Brick> bricks;
  if (!getBricks(&bricks)) return std::nullopt;
  std::vector<Eigen::Vector3d> centres;
  for (const Brick& brick : bricks)
    centres.emplace_back(brick.pose.position.x, brick.pose.position.y, brick.pose.position.z);
  const int nearest = nearestIndex(point, centres);
  if (nearest < 0) {
    ROS_WARN("%s: there is no brick to grasp", action.c_str());
    return std::nullopt;
  }
  if (!graspBrick(bricks[nearest].id)) return std::nullopt;
  return bricks[nearest];
}

bool SimClient::releaseHeld(const geometry_msgs::Twist& twist) {
  if (!held_) {
    ROS_WARN("release: no brick is held");
    return false;
  }
  ReleaseBrick service;
  service.request.id = *held_;
  service.request.twist = twist;
  if (call(release_brick_, service)) {
    held_.reset();
    return true;
  }
  refreshHeld();
  return false;
}

void SimClient::publishHeldTarget(const geometry_msgs::Pose& pose) {
  if (!held_) return;
  geometry_msgs::PoseStamped target;
  target.header.stamp = ros::Time::now();
  target.header.frame_id = kWorldFrame;
  target.pose = pose;
  held_target_.publish(target);
}

void SimClient::refreshHeld() {
  if (!held_) return;
  std::vector<Brick> bricks;
  if (!getBricks(&bricks)) return;  // no answer is no evidence: keep it
  for (const Brick& brick : bricks)
    if (brick.id == *held_ && brick.state == Brick::HELD) return;
  ROS_WARN("%s is no longer held by the simulator", held_->c_str());
  held_.reset();
}

}  // namespace teleop
}  // namespace brick_stack_sim
