#pragma once
// The keyboard teleop's keys and what they do to its cursor: pure functions,
// tested without a terminal or a simulator.

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/teleop/placement_geometry.h"

namespace brick_stack_sim {
namespace teleop {

enum class KeyAction {
  kNone,     ///< Not a key of the map: ignored.
  kMove,     ///< Move the cursor one linear step along a world axis.
  kTurn,     ///< Turn the cursor one angular step about the world z axis.
  kGrasp,    ///< Grasp the brick whose centre is nearest the cursor.
  kRelease,  ///< Release the held brick, at rest.
  kHelp,     ///< Print the key map again.
};

struct KeyCommand {
  KeyAction action = KeyAction::kNone;
  /// kMove: the unit axis of the world frame to move along, signed.
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  /// kTurn: +1 counter-clockwise seen from above, -1 clockwise.
  int turn = 0;
};

struct KeyBinding {
  char key;
  KeyCommand command;
  const char* description;
};

/// Every key of the teleop, in the order the key map prints them.
const std::vector<KeyBinding>& keyBindings();

/// The command of `key`; letters count in either case (caps lock must not
/// make the teleop deaf). Any other key: kNone.
KeyCommand commandForKey(char key);

/// The key map as printed at start and by the help key, one key per line.
std::string keyMapText();

/// Where the teleop points: a pose in the world frame. While a brick is held
/// it is the brick's target.
struct Cursor {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               ///< [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< Unit.
};

struct CursorSteps {
  double linear = 0.005;       ///< One move key [m]: a fifth of a KAPLA width.
  double angular = M_PI / 12;  ///< One turn key [rad]: six presses turn a brick crosswise.
  double min_z = kTableTop;    ///< The cursor never goes below this height [m].
};

/// The lowest the cursor may go [m]: with a brick of `half_extents` [m] held
/// at it, the height at which that brick's lowest corner touches the table
/// top (lowestCentreZ() of the cursor's orientation), so that its target
/// never sinks into the table; the table top itself for zero half extents
/// (nothing held). Non-finite half extents count as zero.
double cursorFloor(const Cursor& cursor, const Eigen::Vector3d& half_extents);
/// The same for a held brick of any shape, `solid` in its frame at the
/// cursor: the height at which its lowest point touches the table top
/// (lowestCentreZ() of the solid); the table top for a solid that is not
/// finite or has no part.
double cursorFloor(const Cursor& cursor, const ConvexSolid& solid);

/// The cursor after `command`: moved along its world axis, or turned about
/// the world z axis (roll and pitch kept), its height never below
/// `steps.min_z`. Commands that do not move it leave it as it is.
Cursor moveCursor(const Cursor& cursor, const KeyCommand& command, const CursorSteps& steps);

}  // namespace teleop
}  // namespace brick_stack_sim
