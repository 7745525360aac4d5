#include "brick_stack_sim/teleop/keyboard_command.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace brick_stack_sim {
namespace teleop {

namespace {

KeyCommand move(double x, double y, double z) {
  KeyCommand command;
  command.action = KeyAction::kMove;
  command.direction = Eigen::Vector3d(x, y, z);
  return command;
}

KeyCommand turn(int sign) {
  KeyCommand command;
  command.action = KeyAction::kTurn;
  command.turn = sign;
  return command;
}

KeyCommand act(KeyAction action) {
  KeyCommand command;
  command.action = action;
  return command;
}

}  // namespace

const std::vector<KeyBinding>& keyBindings() {
  // w/s and a/d as in most games; r/f for up and down sit beside them, and
  // q/e turn as the hand expects next to w.
  static const std::vector<KeyBinding> bindings = {
      {'w', move(1, 0, 0), "move +x"},
      {'s', move(-1, 0, 0), "move -x"},
      {'a', move(0, 1, 0), "move +y"},
      {'d', move(0, -1, 0), "move -y"},
      {'r', move(0, 0, 1), "move up (+z)"},
      {'f', move(0, 0, -1), "move down (-z)"},
      {'q', turn(1), "turn counter-clockwise about z"},
      {'e', turn(-1), "turn clockwise about z"},
      {'g', act(KeyAction::kGrasp), "grasp the brick nearest the cursor"},
      {' ', act(KeyAction::kRelease), "release the held brick (at rest)"},
      {'h', act(KeyAction::kHelp), "print this key map"},
  };
  return bindings;
}

KeyCommand commandForKey(char key) {
  const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(key)));
  for (const KeyBinding& binding : keyBindings())
    if (binding.key == lower) return binding.command;
  return KeyCommand();
}

std::string keyMapText() {
  std::ostringstream text;
  for (const KeyBinding& binding : keyBindings()) {
    text << "  " << (binding.key == ' ' ? std::string("space") : std::string(1, binding.key));
    text << std::string(binding.key == ' ' ? 2 : 6, ' ') << binding.description << "\n";
  }
  text << "  Ctrl-C quit";
  return text.str();
}

double cursorFloor(const Cursor& cursor, const Eigen::Vector3d& half_extents) {
  if (!half_extents.allFinite()) return kTableTop;
  return lowestCentreZ(half_extents, cursor.orientation.normalized().toRotationMatrix());
}

double cursorFloor(const Cursor& cursor, const ConvexSolid& solid) {
  const Eigen::Matrix3d rotation = cursor.orientation.normalized().toRotationMatrix();
  if (!finiteSolid(PlacedSolid{Eigen::Isometry3d(rotation), &solid})) return kTableTop;
  return lowestCentreZ(solid, rotation);
}

Cursor moveCursor(const Cursor& cursor, const KeyCommand& command, const CursorSteps& steps) {
  Cursor moved = cursor;
  switch (command.action) {
    case KeyAction::kMove:
      moved.position += steps.linear * command.direction;
      moved.position.z() = std::max(moved.position.z(), steps.min_z);
      break;
    case KeyAction::kTurn:
      // About the world axis, applied on the left: a brick held on its side
      // stays on its side while it turns.
      moved.orientation =
          (Eigen::AngleAxisd(command.turn * steps.angular, Eigen::Vector3d::UnitZ()) *
           cursor.orientation)
              .normalized();
      break;
    default:
      break;
  }
  return moved;
}

}  // namespace teleop
}  // namespace brick_stack_sim
