#include "brick_stack_sim/teleop/brick_placer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <visualization_msgs/InteractiveMarkerControl.h>
#include <visualization_msgs/Marker.h>

#include "brick_stack_sim/ros/brick_markers.h"
#include "brick_stack_sim/ros/conversions.h"
#include "brick_stack_sim/ros/marker_style.h"
#include "brick_stack_sim/teleop/placement_geometry.h"

namespace brick_stack_sim {
namespace teleop {

namespace {

using visualization_msgs::InteractiveMarker;
using visualization_msgs::InteractiveMarkerControl;
using visualization_msgs::InteractiveMarkerFeedback;
using visualization_msgs::Marker;

/// Translucent, so that the bricks under the ghost stay visible, but opaque
/// enough to stand out from the translucent bricks of the simulator's markers.
constexpr float kGhostAlpha = 0.75f;
/// The handles' size over the brick's longest side [-]: RViz draws a rotate
/// ring from half this size outward, so at 1 its inside just clears the
/// brick's ends, where it can be grabbed, and it is no larger than that.
constexpr double kHandleScale = 1.0;
/// Smallest handle size [m]: a cube's handles would be too small to grab.
constexpr double kMinHandleSize = 0.05;

std::string describe(const Eigen::Vector3d& position) {
  char text[96];
  std::snprintf(text, sizeof(text), "(%.4f, %.4f, %.4f) m", position.x(), position.y(),
                position.z());
  return text;
}

/// One handle: a move or rotate control about the world axis that the
/// quaternion (w, x, y, z) turns the control's x axis onto.
InteractiveMarkerControl handle(const std::string& name, uint8_t mode, double w, double x, double y,
                                double z) {
  InteractiveMarkerControl control;
  control.name = name;
  control.interaction_mode = mode;
  // World-fixed axes: "up" stays up however the ghost is turned.
  control.orientation_mode = InteractiveMarkerControl::FIXED;
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  control.orientation.w = w / norm;
  control.orientation.x = x / norm;
  control.orientation.y = y / norm;
  control.orientation.z = z / norm;
  return control;
}

}  // namespace

BrickPlacer::BrickPlacer(const PlacerOptions& options, const BrickTypeLibrary& types)
    : options_(options),
      types_(types),
      type_(options.type.empty() ? types.defaultType() : options.type),
      sim_(node_handle_, options.teleop.sim),
      server_(ros::this_node::getName()) {
  ghost_pose_.translation() = options.teleop.initial_position;
  ghost_pose_.linear() =
      Eigen::AngleAxisd(options.teleop.initial_yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  buildMenu();
  showGhost();
  ROS_INFO("brick_placer: ghost %s at %s; right-click it in RViz for the menu (marker topic %s)",
           type_.c_str(), describe(ghost_pose_.translation()).c_str(),
           (ros::this_node::getName() + "/update").c_str());
}

void BrickPlacer::waitForSimulator() {
  if (!sim_.waitForSimulator(options_.teleop.wait_for_sim) || !options_.start_beside) return;
  SolidBricks bricks;
  if (!brickSolids(&bricks) || bricks.placed.empty()) return;
  // Beside the structure, on the table: the ghost and its rings hide none
  // of it.
  ghost_pose_.translation() = besideBricks(bricks.placed, *typeSolid(), ghost_pose_.linear(),
                                           options_.teleop.initial_position);
  server_.setPose(kGhostMarker, ros_adapter::toPoseMsg(ghost_pose_));
  server_.applyChanges();
  ROS_INFO("brick_placer: ghost moved beside the %zu bricks, to %s", bricks.placed.size(),
           describe(ghost_pose_.translation()).c_str());
}

bool BrickPlacer::brickSolids(SolidBricks* solids) {
  std::vector<Brick> bricks;
  if (!sim_.getBricks(&bricks)) return false;
  *solids = SolidBricks();
  for (const Brick& brick : bricks) {
    Eigen::Isometry3d pose;
    // The simulator publishes nothing non-finite; a brick that fails the
    // check anyway is left out rather than trusted.
    if (!ros_adapter::fromMsg(brick.pose, "brick pose", &pose)) continue;
    std::shared_ptr<const ConvexSolid> solid =
        brickSolid(types_, brick.type, Eigen::Vector3d(brick.size.x, brick.size.y, brick.size.z));
    if (solid) solids->add(pose, std::move(solid));
  }
  return true;
}

std::shared_ptr<const ConvexSolid> BrickPlacer::typeSolid() const {
  const BrickType& type = *types_.find(type_);
  return type.solid ? type.solid
                    : std::make_shared<const ConvexSolid>(boxSolid(type.halfExtents()));
}

bool BrickPlacer::keepAboveTable(const ConvexSolid& solid, Eigen::Isometry3d* pose) {
  const double lowest = lowestCentreZ(solid, pose->linear());
  if (pose->translation().z() >= lowest) return false;
  pose->translation().z() = lowest;
  return true;
}

void BrickPlacer::buildMenu() {
  menu_.insert(kPlaceHereEntry, [this](const FeedbackConstPtr& f) { placeHere(f); });
  menu_.insert(kDropFromHereEntry, [this](const FeedbackConstPtr& f) { dropFromHere(f); });
  menu_.insert(kTurnEntry, [this](const FeedbackConstPtr& f) { turn(f); });
  const auto type_menu = menu_.insert(kTypeMenu);
  for (const std::string& name : types_.names()) {
    const auto entry = menu_.insert(
        type_menu, name, [this, name](const FeedbackConstPtr& f) { selectType(name, f); });
    menu_.setCheckState(entry, name == type_ ? interactive_markers::MenuHandler::CHECKED
                                             : interactive_markers::MenuHandler::UNCHECKED);
    type_entries_[name] = entry;
  }
  menu_.insert(kGraspEntry, [this](const FeedbackConstPtr& f) { graspNearest(f); });
  menu_.insert(kReleaseEntry, [this](const FeedbackConstPtr& f) { release(f); });
}

void BrickPlacer::showGhost() {
  const bool in_hand = sim_.held().has_value();
  const Eigen::Vector3d size = in_hand ? held_size_ : types_.find(type_)->size;
  const std::shared_ptr<const ConvexSolid> solid = in_hand ? held_solid_ : typeSolid();

  InteractiveMarker ghost;
  ghost.header.frame_id = kWorldFrame;
  ghost.name = kGhostMarker;
  ghost.description = in_hand ? "holding " + *sim_.held() + " (Release in the menu)"
                              : type_ + " (right-click: menu)";
  ghost.pose = ros_adapter::toPoseMsg(ghost_pose_);
  ghost.scale = static_cast<float>(std::max(kMinHandleSize, kHandleScale * size.maxCoeff()));

  // Blue for a brick to be placed, orange for one in hand; drawn as
  // ~markers draws a brick of the shape, relative to the ghost's pose.
  const std_msgs::ColorRGBA color = in_hand ? ros_adapter::rgb(1.0f, 0.55f, 0.1f, kGhostAlpha)
                                            : ros_adapter::rgb(0.2f, 0.6f, 1.0f, kGhostAlpha);
  InteractiveMarkerControl body;
  body.name = "body";
  body.always_visible = true;
  body.interaction_mode = InteractiveMarkerControl::MOVE_3D;
  body.markers =
      ros_adapter::solidBodyMarkers(solid.get(), size, Eigen::Isometry3d::Identity(), color);
  ghost.controls.push_back(body);

  // The quaternions (w, x, y, z) of the interactive_markers tutorials: a
  // control acts along its own x axis, which (1, 1, 0, 0) leaves on world x,
  // (1, 0, 1, 0) turns onto z and (1, 0, 0, 1) onto y.
  ghost.controls.push_back(handle("rotate_x", InteractiveMarkerControl::ROTATE_AXIS, 1, 1, 0, 0));
  ghost.controls.push_back(handle("move_x", InteractiveMarkerControl::MOVE_AXIS, 1, 1, 0, 0));
  ghost.controls.push_back(handle("rotate_z", InteractiveMarkerControl::ROTATE_AXIS, 1, 0, 1, 0));
  ghost.controls.push_back(handle("move_z", InteractiveMarkerControl::MOVE_AXIS, 1, 0, 1, 0));
  ghost.controls.push_back(handle("rotate_y", InteractiveMarkerControl::ROTATE_AXIS, 1, 0, 0, 1));
  ghost.controls.push_back(handle("move_y", InteractiveMarkerControl::MOVE_AXIS, 1, 0, 0, 1));

  server_.insert(
      ghost, [this](const FeedbackConstPtr& f) { onPoseUpdate(f); },
      InteractiveMarkerFeedback::POSE_UPDATE);
  menu_.apply(server_, kGhostMarker);
  server_.applyChanges();
}

bool BrickPlacer::takeFeedbackPose(const FeedbackConstPtr& feedback) {
  const std::string& frame = feedback->header.frame_id;
  if (!frame.empty() && frame != kWorldFrame) {
    ROS_WARN("ghost pose in frame '%s' ignored: the placer works in '%s'", frame.c_str(),
             kWorldFrame);
    return false;
  }
  Eigen::Isometry3d pose;
  if (Status converted = ros_adapter::fromMsg(feedback->pose, "ghost pose", &pose); !converted) {
    ROS_WARN("ignored: %s", converted.message.c_str());
    return false;
  }
  ghost_pose_ = pose;
  return true;
}

void BrickPlacer::onPoseUpdate(const FeedbackConstPtr& feedback) {
  if (!takeFeedbackPose(feedback) || !sim_.held()) return;
  // The held brick's target stays above the table (the simulator would
  // refuse it); the ghost shows where the target is.
  if (held_solid_ && keepAboveTable(*held_solid_, &ghost_pose_)) {
    server_.setPose(kGhostMarker, ros_adapter::toPoseMsg(ghost_pose_));
    server_.applyChanges();
  }
  sim_.publishHeldTarget(ros_adapter::toPoseMsg(ghost_pose_));
}

bool BrickPlacer::holding() {
  if (!sim_.held()) return false;
  sim_.refreshHeld();
  if (!sim_.held()) showGhost();  // back to the current type's look
  return sim_.held().has_value();
}

bool BrickPlacer::readyToPlace(const char* action) {
  if (!holding()) return true;
  ROS_WARN("%s: %s is held and the ghost is on it; Release it first", action, sim_.held()->c_str());
  return false;
}

void BrickPlacer::place(const Eigen::Isometry3d& pose, const char* action) {
  std::string id;
  if (sim_.placeBrick(type_, ros_adapter::toPoseMsg(pose), &id))
    ROS_INFO("%s: placed %s (%s) at %s", action, id.c_str(), type_.c_str(),
             describe(pose.translation()).c_str());
}

void BrickPlacer::placeHere(const FeedbackConstPtr& feedback) {
  if (!readyToPlace(kPlaceHereEntry) || !takeFeedbackPose(feedback)) return;
  SolidBricks bricks;
  if (!brickSolids(&bricks)) return;
  const std::shared_ptr<const ConvexSolid> solid = typeSolid();
  place(restingPose(PlacedSolid{ghost_pose_, solid.get()}, bricks.placed), kPlaceHereEntry);
}

void BrickPlacer::dropFromHere(const FeedbackConstPtr& feedback) {
  if (!readyToPlace(kDropFromHereEntry) || !takeFeedbackPose(feedback)) return;
  Eigen::Isometry3d pose = ghost_pose_;
  keepAboveTable(*typeSolid(), &pose);
  place(pose, kDropFromHereEntry);
}

void BrickPlacer::turn(const FeedbackConstPtr& feedback) {
  if (!takeFeedbackPose(feedback)) return;
  ghost_pose_.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                         ghost_pose_.linear();
  const geometry_msgs::Pose pose = ros_adapter::toPoseMsg(ghost_pose_);
  server_.setPose(kGhostMarker, pose);
  server_.applyChanges();
  if (sim_.held()) sim_.publishHeldTarget(pose);
}

void BrickPlacer::selectType(const std::string& type, const FeedbackConstPtr& feedback) {
  takeFeedbackPose(feedback);  // a bad pose does not stop a type change
  type_ = type;
  for (const auto& [name, entry] : type_entries_)
    menu_.setCheckState(entry, name == type_ ? interactive_markers::MenuHandler::CHECKED
                                             : interactive_markers::MenuHandler::UNCHECKED);
  showGhost();
  ROS_INFO("type %s: %s", type_.c_str(),
           sim_.held() ? "used for the next brick after Release" : "the ghost's size changed");
}

void BrickPlacer::graspNearest(const FeedbackConstPtr& feedback) {
  if (holding()) {
    ROS_WARN("%s: %s is already held (one at a time); Release it first", kGraspEntry,
             sim_.held()->c_str());
    return;
  }
  if (!takeFeedbackPose(feedback)) return;
  const std::optional<Brick> grasped = sim_.graspNearest(ghost_pose_.translation(), kGraspEntry);
  if (!grasped) return;
  const Brick& brick = *grasped;
  // The ghost jumps onto the brick, so that the first drag moves the brick
  // from where it is rather than to where the ghost was.
  Eigen::Isometry3d pose;
  if (ros_adapter::fromMsg(brick.pose, "brick pose", &pose)) ghost_pose_ = pose;
  held_size_ = Eigen::Vector3d(brick.size.x, brick.size.y, brick.size.z);
  held_solid_ = brickSolid(types_, brick.type, held_size_);
  showGhost();
  ROS_INFO("holding %s: drag the ghost to move it, Release lets it go", brick.id.c_str());
}

void BrickPlacer::release(const FeedbackConstPtr& feedback) {
  takeFeedbackPose(feedback);
  if (!sim_.held()) {
    ROS_WARN("%s: no brick is held", kReleaseEntry);
    return;
  }
  const std::string id = *sim_.held();
  if (sim_.releaseHeld(geometry_msgs::Twist())) ROS_INFO("released %s", id.c_str());
  // Also after a refusal that showed the brick is no longer held.
  if (!sim_.held()) showGhost();
}

}  // namespace teleop
}  // namespace brick_stack_sim
