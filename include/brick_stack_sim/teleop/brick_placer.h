#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <interactive_markers/interactive_marker_server.h>
#include <interactive_markers/menu_handler.h>
#include <ros/ros.h>
#include <visualization_msgs/InteractiveMarker.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/teleop/placement_geometry.h"
#include "brick_stack_sim/teleop/sim_session.h"
#include "brick_stack_sim/teleop/teleop_options.h"

namespace brick_stack_sim {
namespace teleop {

// The ghost's interactive marker and its menu, as RViz shows them; tests
// find the menu entries by these titles.
constexpr char kGhostMarker[] = "ghost";
constexpr char kPlaceHereEntry[] = "Place here";
constexpr char kDropFromHereEntry[] = "Drop from here";
constexpr char kTurnEntry[] = "Turn 90 degrees";
constexpr char kTypeMenu[] = "Type";
constexpr char kGraspEntry[] = "Grasp nearest brick";
constexpr char kReleaseEntry[] = "Release";

/// An interactive-marker server with a translucent ghost brick that a user
/// moves and turns in RViz (6-DOF handles) and a right-click menu that
/// places bricks where the ghost is, changes its type, and grasps, moves and
/// releases a brick of the simulator. The server's topics live in the node's
/// own namespace (`<node name>/update`, `<node name>/feedback`). Every action
/// is a service call to the simulator; what the simulator refuses is logged
/// at WARN with its message. Runs in the ros::spin thread.
class BrickPlacer {
 public:
  /// Shows the ghost at options.teleop.initial_position / initial_yaw with
  /// the type options.type (default: the types' default type). `types` must
  /// not be empty.
  BrickPlacer(const PlacerOptions& options, const BrickTypeLibrary& types);

  BrickPlacer(const BrickPlacer&) = delete;
  BrickPlacer& operator=(const BrickPlacer&) = delete;

  /// Waits for the simulator for options.teleop.wait_for_sim and logs the
  /// outcome; the placer works either way once the simulator is there. With
  /// options.start_beside, the ghost then moves beside the bricks the
  /// simulator has, resting on the table top.
  void waitForSimulator();

 private:
  using FeedbackConstPtr = visualization_msgs::InteractiveMarkerFeedbackConstPtr;

  void buildMenu();
  /// (Re)publishes the ghost: the current type's shape, or the held brick's
  /// shape and another colour while a brick is held (solidBodyMarkers()).
  void showGhost();
  /// Takes the feedback's pose as the ghost's; false (logged) when it is not
  /// finite, not a unit quaternion or not in the world frame.
  bool takeFeedbackPose(const FeedbackConstPtr& feedback);
  /// The simulator's bricks as solids (those with a finite pose and size),
  /// each its type's from types_ or the box of its size (brickSolid());
  /// false when it does not answer.
  bool brickSolids(SolidBricks* bricks);
  /// The current type's solid (the box of its size should it have none).
  std::shared_ptr<const ConvexSolid> typeSolid() const;
  /// Keeps `*pose` from sinking into the table: a brick of `solid` there
  /// would have its lowest point at the table top at least
  /// (lowestCentreZ()). True when it had to be raised.
  static bool keepAboveTable(const ConvexSolid& solid, Eigen::Isometry3d* pose);

  void onPoseUpdate(const FeedbackConstPtr& feedback);
  void placeHere(const FeedbackConstPtr& feedback);
  void dropFromHere(const FeedbackConstPtr& feedback);
  void turn(const FeedbackConstPtr& feedback);
  void selectType(const std::string& type, const FeedbackConstPtr& feedback);
  void graspNearest(const FeedbackConstPtr& feedback);
  void release(const FeedbackConstPtr& feedback);

  /// Whether the simulator still holds the brick this placer grasped; a
  /// brick it lost (a reset, a removal) is forgotten and the ghost restored.
  bool holding();
  /// Whether a place request may go ahead: no brick is held (the ghost is
  /// then the held brick, and a new one would be placed inside it).
  bool readyToPlace(const char* action);
  void place(const Eigen::Isometry3d& pose, const char* action);

  PlacerOptions options_;
  BrickTypeLibrary types_;
  std::string type_;
  Eigen::Isometry3d ghost_pose_ = Eigen::Isometry3d::Identity();
  /// Bounds' full extents of the held brick [m].
  Eigen::Vector3d held_size_ = Eigen::Vector3d::Zero();
  /// The held brick's solid (brickSolid()); null: none held, or of no finite size.
  std::shared_ptr<const ConvexSolid> held_solid_;

  ros::NodeHandle node_handle_;
  SimSession sim_;
  interactive_markers::InteractiveMarkerServer server_;
  interactive_markers::MenuHandler menu_;
  std::map<std::string, interactive_markers::MenuHandler::EntryHandle> type_entries_;
};

}  // namespace teleop
}  // namespace brick_stack_sim
