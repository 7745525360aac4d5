#pragma once
// What the teleop nodes ask of the simulator, over the client library: every
// failure or refusal is logged at WARN with the simulator's own message, so
// that a user always sees why an action did nothing, and the brick the user
// holds is tracked.

#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>
#include <ros/node_handle.h>

#include <Eigen/Core>

#include "brick_stack_sim/Brick.h"
#include "brick_stack_sim/client/sim_client.h"
#include "brick_stack_sim/ros/interface_names.h"

namespace brick_stack_sim {
namespace teleop {

/// The frame of every pose the simulator takes and gives.
using ros_adapter::kWorldFrame;

/// One user's session with the simulator whose private namespace is
/// `sim_namespace`: its services through one client::SimClient (persistent
/// connections), its ~held_target, and the brick the user holds. Used from
/// one thread (the node's spin or key loop).
class SimSession {
 public:
  /// Advertises ~held_target at once, so that the simulator is connected to
  /// it before the first grasp.
  SimSession(ros::NodeHandle node_handle, const std::string& sim_namespace);

  /// Waits up to `timeout` [s] for the simulator's services, logs whether it
  /// came up, and returns whether it did. Nothing depends on the answer: each
  /// call waits again, so a simulator started later is still found.
  bool waitForSimulator(double timeout);

  /// Every brick, or false (logged) when the simulator does not answer.
  bool getBricks(std::vector<Brick>* bricks);
  /// ~place_brick of a brick of `type` at `pose` [m], at rest; `*id` receives
  /// the name the simulator gave it.
  bool placeBrick(const std::string& type, const geometry_msgs::Pose& pose, std::string* id);
  /// ~grasp_brick; on success the brick is the held one.
  bool graspBrick(const std::string& id);
  /// ~grasp_brick of the brick whose centre is nearest `point` [m]; the
  /// grasped brick, or nothing (logged, with `action` naming what the user
  /// asked for) when there is none or the simulator refuses.
  std::optional<Brick> graspNearest(const Eigen::Vector3d& point, const std::string& action);
  /// ~release_brick of the held brick with `twist` [m/s, rad/s]. Whatever
  /// the answer, a brick the simulator no longer holds is forgotten.
  bool releaseHeld(const geometry_msgs::Twist& twist);
  /// Publishes `pose` as ~held_target (frame world), while a brick is held.
  void publishHeldTarget(const geometry_msgs::Pose& pose);

  /// The brick this session grasped and has not released, if any.
  const std::optional<std::string>& held() const { return held_; }
  /// Forgets the held brick when the simulator no longer reports it HELD (it
  /// was removed, the scene was reset, someone else released it).
  void refreshHeld();

  const std::string& simNamespace() const { return sim_.options().sim_namespace; }

 private:
  /// Whether `reply` is an acceptance; logs why not.
  bool accepted(const client::CallResult& reply) const;

  client::SimClient sim_;
  std::optional<std::string> held_;
};

}  // namespace teleop
}  // namespace brick_stack_sim
