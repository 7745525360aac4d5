#pragma once

#include <memory>

#include <ros/ros.h>

#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/teleop/keyboard_command.h"
#include "brick_stack_sim/teleop/raw_terminal.h"
#include "brick_stack_sim/teleop/sim_session.h"
#include "brick_stack_sim/teleop/teleop_options.h"

namespace brick_stack_sim {
namespace teleop {

/// A terminal teleop: keys move a cursor (and the brick held at it) and turn
/// it about z, one key grasps the brick nearest the cursor, one releases it
/// (keyBindings()). While a brick is held, the cursor is published as the
/// simulator's ~held_target on every key and at options.held_target_rate; the
/// cursor itself is shown in RViz as an arrow on `~cursor`.
class KeyboardTeleop {
 public:
  explicit KeyboardTeleop(const KeyboardOptions& options);

  /// Prints the key map and handles keys from `terminal` until ROS shuts down
  /// (Ctrl-C) or the input ends.
  void run(RawTerminal& terminal);

 private:
  void handle(const KeyCommand& command);
  void grasp();
  void release();
  /// The cursor as a marker and, while a brick is held, as its target.
  void publishCursor();
  void printCursor() const;

  KeyboardOptions options_;
  ros::NodeHandle node_handle_;
  SimSession sim_;
  Cursor cursor_;
  /// Loads the simulator's brick types (loadPlacerTypes()); without them
  /// every brick counts as the box of its size.
  void loadTypes();

  /// The simulator's brick types, for the held brick's solid (brickSolid()).
  BrickTypeLibrary types_;
  /// Half the bounds' extents of the held brick [m] (zero when none): the
  /// cursor arrow's length.
  Eigen::Vector3d held_half_extents_ = Eigen::Vector3d::Zero();
  /// The held brick's solid in its frame (null when none, or of no finite
  /// size): the cursor stays high enough for it to clear the table
  /// (cursorFloor()).
  std::shared_ptr<const ConvexSolid> held_solid_;
  ros::Publisher cursor_marker_;
};

}  // namespace teleop
}  // namespace brick_stack_sim
