// The words and conversions of a brick's mode in the world.
#include "world/brick_record.h"

namespace brick_stack_sim {

const char* toString(BrickMode mode) {
  switch (mode) {
    case BrickMode::kDynamic:
      return "dynamic";
    case BrickMode::kFrozenStable:
      return "frozen-stable";
    case BrickMode::kFrozenLeaning:
      return "frozen-leaning";
    case BrickMode::kHeld:
      return "held";
  }
  return "unknown";
}

BrickState toState(BrickMode mode) {
  switch (mode) {
    case BrickMode::kDynamic:
      return BrickState::kDynamic;
    case BrickMode::kFrozenStable:
      return BrickState::kStable;
    case BrickMode::kFrozenLeaning:
      return BrickState::kLeaning;
    case BrickMode::kHeld:
      return BrickState::kHeld;
  }
  return BrickState::kDynamic;
}

BrickMode frozenMode(BrickState kind) {
  return kind == BrickState::kLeaning ? BrickMode::kFrozenLeaning : BrickMode::kFrozenStable;
}

}  // namespace brick_stack_sim
