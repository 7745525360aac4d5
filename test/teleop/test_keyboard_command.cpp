// The keyboard teleop's key map and cursor, without a terminal.
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/teleop/keyboard_command.h"
#include "support/kapla.h"

namespace {

using namespace brick_stack_sim::teleop;

void expectMove(char key, const Eigen::Vector3d& direction) {
  const KeyCommand command = commandForKey(key);
  EXPECT_EQ(command.action, KeyAction::kMove) << "key '" << key << "'";
  EXPECT_TRUE(command.direction.isApprox(direction))
      << "key '" << key << "' moves along " << command.direction.transpose();
}

TEST(KeyMap, MoveTurnGraspReleaseKeys) {
  expectMove('w', Eigen::Vector3d::UnitX());
  expectMove('s', -Eigen::Vector3d::UnitX());
  expectMove('a', Eigen::Vector3d::UnitY());
  expectMove('d', -Eigen::Vector3d::UnitY());
  expectMove('r', Eigen::Vector3d::UnitZ());
  expectMove('f', -Eigen::Vector3d::UnitZ());
  EXPECT_EQ(commandForKey('q').action, KeyAction::kTurn);
  EXPECT_EQ(commandForKey('q').turn, 1);
  EXPECT_EQ(commandForKey('e').action, KeyAction::kTurn);
  EXPECT_EQ(commandForKey('e').turn, -1);
  EXPECT_EQ(commandForKey('g').action, KeyAction::kGrasp);
  EXPECT_EQ(commandForKey(' ').action, KeyAction::kRelease);
  EXPECT_EQ(commandForKey('h').action, KeyAction::kHelp);
}

TEST(KeyMap, CapsLockDoesNotMatter) {
  expectMove('W', Eigen::Vector3d::UnitX());
  expectMove('F', -Eigen::Vector3d::UnitZ());
  EXPECT_EQ(commandForKey('G').action, KeyAction::kGrasp);
}

TEST(KeyMap, OtherKeysDoNothing) {
  for (char key : std::string("zxcvbnmy\n\t\x1b\x03"
                              "0123456789[]"))
    EXPECT_EQ(commandForKey(key).action, KeyAction::kNone) << "key code " << int(key);
}

TEST(KeyMap, PrintedMapNamesEveryKeyOnce) {
  const std::string text = keyMapText();
  std::set<char> keys;
  for (const KeyBinding& binding : keyBindings()) {
    EXPECT_TRUE(keys.insert(binding.key).second) << "key '" << binding.key << "' bound twice";
    EXPECT_NE(text.find(binding.description), std::string::npos) << binding.description;
  }
  EXPECT_NE(text.find("space"), std::string::npos);
  EXPECT_NE(text.find("Ctrl-C"), std::string::npos);
}

Cursor startCursor() {
  Cursor cursor;
  cursor.position = Eigen::Vector3d(0.0, 0.0, 0.05);
  return cursor;
}

Cursor press(Cursor cursor, const std::string& keys, const CursorSteps& steps = CursorSteps()) {
  for (char key : keys) cursor = moveCursor(cursor, commandForKey(key), steps);
  return cursor;
}

TEST(Cursor, MoveKeysStepAlongWorldAxes) {
  CursorSteps steps;
  steps.linear = 0.005;
  const Cursor moved = press(startCursor(), "wwwaddr", steps);
  EXPECT_NEAR(moved.position.x(), 0.015, 1e-12);
  EXPECT_NEAR(moved.position.y(), -0.005, 1e-12);
  EXPECT_NEAR(moved.position.z(), 0.055, 1e-12);
  // Turned, the cursor still moves along the world's x, not its own.
  const Cursor turned = press(startCursor(), "qqqqqqw", steps);  // 6 x 15 degrees
  EXPECT_NEAR(turned.position.x(), 0.005, 1e-12);
  EXPECT_NEAR(turned.position.y(), 0.0, 1e-12);
}

TEST(Cursor, NeverBelowTheTable) {
  CursorSteps steps;
  steps.linear = 0.02;
  const Cursor down = press(startCursor(), "ffff", steps);
  EXPECT_EQ(down.position.z(), 0.0);
  EXPECT_NEAR(press(down, "r", steps).position.z(), 0.02, 1e-12);
}

/// Keys pressed as keyboard_teleop presses them while it holds a brick of
/// `half_extents`: each move's floor is cursorFloor() of the cursor then.
Cursor pressHolding(Cursor cursor, const std::string& keys, const Eigen::Vector3d& half_extents,
                    CursorSteps steps) {
  for (char key : keys) {
    steps.min_z = cursorFloor(cursor, half_extents);
    cursor = moveCursor(cursor, commandForKey(key), steps);
  }
  return cursor;
}

TEST(Cursor, HoldingABrickItStopsWhereTheBrickRestsOnTheTable) {
  using brick_stack_sim::test::kKaplaLength;
  using brick_stack_sim::test::kKaplaThickness;
  using brick_stack_sim::test::kKaplaWidth;
  const Eigen::Vector3d half = 0.5 * Eigen::Vector3d(kKaplaLength, kKaplaWidth, kKaplaThickness);
  CursorSteps steps;
  steps.linear = 0.007;  // not a divisor of the height: the last step is cut short
  // Flat: the centre stops half a plank's thickness above the table top,
  // so the plank's underside lies on it.
  const Cursor flat = pressHolding(startCursor(), std::string(20, 'f'), half, steps);
  EXPECT_NEAR(flat.position.z(), 0.5 * kKaplaThickness, 1e-12);
  EXPECT_NEAR(flat.position.z() - half.z(), kTableTop, 1e-12);
  // Turning about z keeps it there; moving sideways too.
  EXPECT_NEAR(pressHolding(flat, "qqwad", half, steps).position.z(), 0.5 * kKaplaThickness, 1e-12);
  // On its edge (turned 90 degrees about x): half its width.
  Cursor edge = startCursor();
  edge.orientation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(pressHolding(edge, std::string(20, 'f'), half, steps).position.z(), 0.5 * kKaplaWidth,
              1e-12);
  // On its end (turned 90 degrees about y), from higher up: half its length.
  Cursor end = startCursor();
  end.position.z() = 0.2;
  end.orientation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY());
  EXPECT_NEAR(pressHolding(end, std::string(60, 'f'), half, steps).position.z(), 0.5 * kKaplaLength,
              1e-12);
  // Tilted 30 degrees about x: the lowest edge touches the table top.
  Cursor tilted = startCursor();
  tilted.orientation = Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(pressHolding(tilted, std::string(20, 'f'), half, steps).position.z(),
              half.y() * std::sin(M_PI / 6) + half.z() * std::cos(M_PI / 6), 1e-12);
  // Nothing held (zero or unknown half extents): the cursor's point itself
  // stops at the table top.
  EXPECT_EQ(pressHolding(startCursor(), std::string(20, 'f'), Eigen::Vector3d::Zero(), steps)
                .position.z(),
            kTableTop);
  EXPECT_EQ(cursorFloor(startCursor(), Eigen::Vector3d::Constant(std::nan(""))), kTableTop);
}

TEST(Cursor, TurnKeysTurnAboutWorldZ) {
  CursorSteps steps;
  steps.angular = M_PI / 12;
  const Cursor quarter = press(startCursor(), "qqqqqq", steps);
  const Eigen::Vector3d heading = quarter.orientation * Eigen::Vector3d::UnitX();
  EXPECT_TRUE(heading.isApprox(Eigen::Vector3d::UnitY(), 1e-12)) << heading.transpose();
  EXPECT_TRUE(quarter.position.isApprox(startCursor().position));
  // e undoes q; 24 steps are a full turn.
  EXPECT_TRUE(
      press(quarter, "eeeeee", steps).orientation.isApprox(Eigen::Quaterniond::Identity(), 1e-12));
  const Cursor full = press(startCursor(), std::string(24, 'q'), steps);
  EXPECT_NEAR(full.orientation.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-9);
}

TEST(Cursor, TurningABrickOnItsSideKeepsItOnItsSide) {
  Cursor on_side = startCursor();
  on_side.orientation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX());
  const Cursor turned = press(on_side, "qq");
  // A turn about world z changes no axis's height.
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d before = on_side.orientation * Eigen::Vector3d::Unit(axis);
    const Eigen::Vector3d after = turned.orientation * Eigen::Vector3d::Unit(axis);
    EXPECT_NEAR(after.z(), before.z(), 1e-12) << "axis " << axis;
  }
  EXPECT_FALSE(turned.orientation.isApprox(on_side.orientation, 1e-6));
}

TEST(Cursor, GraspReleaseAndUnknownKeysLeaveItAlone) {
  const Cursor start = press(startCursor(), "wq");
  for (char key : std::string("g hz")) {
    const Cursor after = press(start, std::string(1, key));
    EXPECT_TRUE(after.position == start.position) << "key '" << key << "'";
    EXPECT_TRUE(after.orientation.coeffs() == start.orientation.coeffs()) << "key '" << key << "'";
  }
}

}  // namespace
