#pragma once
// What the teleop nodes ask of the simulator (DESIGN.md section 3), in one
// place: every call waits briefly for its service, and every failure or
// refusal is logged at WARN with the simulator's own message, so that a user
// always sees why an action did nothing.

#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <Eigen/Core>

#include "brick_stack_sim/Brick.h"

namespace brick_stack_sim {
namespace teleop {

/// The frame of every pose the simulator takes and gives (DESIGN.md section 3).
constexpr char kWorldFrame[] = "world";

class SimClient {
 public:
  /// Clients of the services of the simulator whose private namespace is
  /// `sim_namespace` (e.g. "/brick_sim"), and the publisher of its ~held_target.
  SimClient(ros::NodeHandle node_handle, const std::string& sim_namespace);

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

  /// The brick this client grasped and has not released, if any.
  const std::optional<std::string>& held() const { return held_; }
  /// Forgets the held brick when the simulator no longer reports it HELD (it
  /// was removed, the scene was reset, someone else released it).
  void refreshHeld();

  const std::string& simNamespace() const { return sim_namespace_; }

 private:
  /// Calls `client` after waiting for it for a moment; logs why when the
  /// call fails or the simulator refuses.
  template <typename Service>
  bool call(ros::ServiceClient& client, Service& service);

  std::string sim_namespace_;
  ros::NodeHandle node_handle_;
  ros::ServiceClient get_bricks_;
  ros::ServiceClient place_brick_;
  ros::ServiceClient grasp_brick_;
  ros::ServiceClient release_brick_;
  ros::Publisher held_target_;
  std::optional<std::string> held_;
};

}  // namespace teleop
}  // namespace brick_stack_sim
