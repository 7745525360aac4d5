#include "brick_stack_sim/teleop/sim_session.h"

#include <utility>

#include <ros/console.h>

#include "brick_stack_sim/teleop/placement_geometry.h"

namespace brick_stack_sim {
namespace teleop {

namespace {

/// How long a call waits for its service [s]: long enough to ride out a
/// simulator that is just starting, short enough that a click in RViz on a
/// dead simulator answers at once with a warning.
constexpr double kCallWait = 1.0;

client::ClientOptions sessionOptions(const std::string& sim_namespace) {
  client::ClientOptions options;
  options.sim_namespace = sim_namespace;
  options.service_wait = kCallWait;
  return options;
}

}  // namespace

SimSession::SimSession(ros::NodeHandle node_handle, const std::string& sim_namespace)
    : sim_(sessionOptions(sim_namespace), std::move(node_handle)) {
  sim_.advertiseHeldTarget();
}

bool SimSession::waitForSimulator(double timeout) {
  const client::CallResult up = sim_.waitForNode(timeout);
  if (!up.ok) {
    ROS_WARN("no simulator: %s (parameter ~sim = '%s'); every action will say so until it does",
             up.message.c_str(), simNamespace().c_str());
    return false;
  }
  ROS_INFO("simulator found at %s", simNamespace().c_str());
  return true;
}

bool SimSession::accepted(const client::CallResult& reply) const {
  if (reply.ok) return true;
  if (reply.reached)
    ROS_WARN("%s refused: %s", reply.service.c_str(), reply.message.c_str());
  else
    ROS_WARN("%s: is the simulator running at %s (parameter ~sim)?", reply.message.c_str(),
             simNamespace().c_str());
  return false;
}

bool SimSession::getBricks(std::vector<Brick>* bricks) {
  auto reply = sim_.getBricks();
  if (!accepted(reply)) return false;
  *bricks = std::move(reply.response.bricks);
  return true;
}

bool SimSession::placeBrick(const std::string& type, const geometry_msgs::Pose& pose,
                            std::string* id) {
  PlaceBrick::Request request;
  request.type = type;
  request.pose = pose;
  const auto reply = sim_.placeBrick(request);
  if (!accepted(reply)) return false;
  *id = reply.response.id;
  return true;
}

bool SimSession::graspBrick(const std::string& id) {
  if (!accepted(sim_.graspBrick(id))) return false;
  held_ = id;
  return true;
}

std::optional<Brick> SimSession::graspNearest(const Eigen::Vector3d& point,
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

bool SimSession::releaseHeld(const geometry_msgs::Twist& twist) {
  if (!held_) {
    ROS_WARN("release: no brick is held");
    return false;
  }
  if (accepted(sim_.releaseBrick(*held_, twist))) {
    held_.reset();
    return true;
  }
  refreshHeld();
  return false;
}

void SimSession::publishHeldTarget(const geometry_msgs::Pose& pose) {
  if (held_) sim_.publishHeldTarget(pose);
}

void SimSession::refreshHeld() {
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
