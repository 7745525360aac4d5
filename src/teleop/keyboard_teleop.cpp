#include "brick_stack_sim/teleop/keyboard_teleop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <visualization_msgs/Marker.h>

#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace teleop {

namespace {

/// How often the loop looks for a key and for ROS callbacks [s]: keys feel
/// immediate and a shutdown is noticed at once.
constexpr double kKeyPollPeriod = 0.02;
/// The cursor arrow's length [m] with nothing held: a KAPLA's length, so
/// that it reads from config/teleop.rviz's default view as a brick does.
/// While a brick is held, the arrow is as long as that brick's longest side.
constexpr double kArrowLength = 0.117;
/// The arrow's thickness over its length [-]: half a KAPLA's width at a
/// KAPLA's length, a shaft that shows from the default view.
constexpr double kArrowThickness = 0.1;

geometry_msgs::Pose toPose(const Cursor& cursor) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = cursor.position;
  pose.linear() = cursor.orientation.toRotationMatrix();
  return ros_adapter::toPoseMsg(pose);
}

}  // namespace

KeyboardTeleop::KeyboardTeleop(const KeyboardOptions& options)
    : options_(options), node_handle_("~"), sim_(ros::NodeHandle(), options.teleop.sim) {
  cursor_.position = options.teleop.initial_position;
  cursor_.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(options.teleop.initial_yaw, Eigen::Vector3d::UnitZ()));
  // Latched: RViz started after a key press still shows where the cursor is.
  cursor_marker_ = node_handle_.advertise<visualization_msgs::Marker>("cursor", 1, true);
}

void KeyboardTeleop::run(RawTerminal& terminal) {
  std::printf("keyboard_teleop: keys (steps %g m, %g deg)\n%s\n", options_.steps.linear,
              options_.steps.angular * 180.0 / M_PI, keyMapText().c_str());
  std::fflush(stdout);
  sim_.waitForSimulator(options_.teleop.wait_for_sim);
  loadTypes();
  publishCursor();
  printCursor();
  const ros::WallDuration target_period(1.0 / options_.held_target_rate);
  ros::WallTime next_target = ros::WallTime::now() + target_period;
  while (ros::ok() && !terminal.inputEnded()) {
    char key = 0;
    if (terminal.readKey(kKeyPollPeriod, &key)) handle(commandForKey(key));
    ros::spinOnce();
    // Repeated so that a target lost on the way, or sent before the
    // simulator subscribed, does not leave the brick short of the cursor.
    if (sim_.held() && ros::WallTime::now() >= next_target) {
      sim_.publishHeldTarget(toPose(cursor_));
      next_target = ros::WallTime::now() + target_period;
    }
  }
  if (terminal.inputEnded()) std::printf("keyboard_teleop: input ended\n");
}

void KeyboardTeleop::handle(const KeyCommand& command) {
  switch (command.action) {
    case KeyAction::kNone:
      return;
    case KeyAction::kHelp:
      std::printf("%s\n", keyMapText().c_str());
      break;
    case KeyAction::kGrasp:
      grasp();
      break;
    case KeyAction::kRelease:
      release();
      break;
    case KeyAction::kMove:
    case KeyAction::kTurn: {
      CursorSteps steps = options_.steps;
      if (sim_.held() && held_solid_)
        steps.min_z = std::max(steps.min_z, cursorFloor(cursor_, *held_solid_));
      cursor_ = moveCursor(cursor_, command, steps);
      publishCursor();
      break;
    }
  }
  printCursor();
}

void KeyboardTeleop::grasp() {
  // A brick lost meanwhile (a reset, a removal) must not block a new grasp.
  sim_.refreshHeld();
  if (sim_.held()) {
    ROS_WARN("grasp: %s is already held (one at a time); release it first", sim_.held()->c_str());
    return;
  }
  const std::optional<Brick> grasped = sim_.graspNearest(cursor_.position, "grasp");
  if (!grasped) return;
  const Brick& brick = *grasped;
  // The cursor jumps onto the brick: the next key moves the brick by one
  // step from where it is, not to where the cursor was.
  Eigen::Isometry3d pose;
  if (ros_adapter::fromMsg(brick.pose, "brick pose", &pose)) {
    cursor_.position = pose.translation();
    cursor_.orientation = Eigen::Quaterniond(pose.linear()).normalized();
  }
  const Eigen::Vector3d size(brick.size.x, brick.size.y, brick.size.z);
  held_half_extents_ = size.allFinite() ? Eigen::Vector3d(0.5 * size) : Eigen::Vector3d::Zero();
  held_solid_ = brickSolid(types_, brick.type, size);
  publishCursor();
  std::printf("holding %s\n", brick.id.c_str());
}

void KeyboardTeleop::loadTypes() {
  // The simulator's files, as the placer reads them: it is up by now, so
  // its ~types_urdf is what its bricks were made of.
  PlacerOptions placer;
  placer.teleop = options_.teleop;
  if (Status loaded = loadPlacerTypes(placer, &types_); !loaded)
    ROS_WARN("keyboard_teleop: every held brick counts as the box of its size: %s",
             loaded.message.c_str());
}

void KeyboardTeleop::release() {
  if (!sim_.held()) {
    ROS_WARN("release: no brick is held");
    return;
  }
  const std::string id = *sim_.held();
  if (sim_.releaseHeld(geometry_msgs::Twist())) std::printf("released %s\n", id.c_str());
  publishCursor();
}

void KeyboardTeleop::publishCursor() {
  const geometry_msgs::Pose pose = toPose(cursor_);
  const bool holding = sim_.held().has_value();
  const double length = holding && held_half_extents_.maxCoeff() > 0.0
                            ? 2.0 * held_half_extents_.maxCoeff()
                            : kArrowLength;
  visualization_msgs::Marker arrow;
  arrow.header.frame_id = kWorldFrame;
  arrow.header.stamp = ros::Time::now();
  arrow.ns = "cursor";
  arrow.id = 0;
  arrow.type = visualization_msgs::Marker::ARROW;
  arrow.pose = pose;
  arrow.scale.x = length;
  arrow.scale.y = kArrowThickness * length;
  arrow.scale.z = kArrowThickness * length;
  // Yellow while free, cyan while a brick follows it: neither is a brick's
  // tint nor a ray's green.
  arrow.color.r = holding ? 0.0f : 1.0f;
  arrow.color.g = holding ? 0.85f : 0.9f;
  arrow.color.b = holding ? 1.0f : 0.0f;
  arrow.color.a = 1.0f;
  cursor_marker_.publish(arrow);
  if (holding) sim_.publishHeldTarget(pose);
}

void KeyboardTeleop::printCursor() const {
  const Eigen::Vector3d x_axis = cursor_.orientation * Eigen::Vector3d::UnitX();
  std::printf("cursor (%.4f, %.4f, %.4f) m, heading %.1f deg%s%s\n", cursor_.position.x(),
              cursor_.position.y(), cursor_.position.z(),
              std::atan2(x_axis.y(), x_axis.x()) * 180.0 / M_PI, sim_.held() ? ", holding " : "",
              sim_.held() ? sim_.held()->c_str() : "");
  std::fflush(stdout);
}

}  // namespace teleop
}  // namespace brick_stack_sim
