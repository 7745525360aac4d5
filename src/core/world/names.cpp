// The words the core uses for its enums in reports and logs.
#include "brick_stack_sim/core/brick.h"
#include "brick_stack_sim/core/sim_event.h"
#include "world/brick_record.h"

namespace brick_stack_sim {

const char* toString(BrickState state) {
  switch (state) {
    case BrickState::kDynamic:
      return "dynamic";
    case BrickState::kStable:
      return "stable";
    case BrickState::kLeaning:
      return "leaning";
    case BrickState::kHeld:
      return "held";
  }
  return "unknown";
}

const char* toString(SimEventKind kind) {
  switch (kind) {
    case SimEventKind::kSpawned:
      return "spawned";
    case SimEventKind::kFrozen:
      return "frozen";
    case SimEventKind::kWoken:
      return "woken";
    case SimEventKind::kImpact:
      return "impact";
    case SimEventKind::kFellOff:
      return "fell_off";
    case SimEventKind::kRemoved:
      return "removed";
    case SimEventKind::kNonFinite:
      return "nonfinite";
    case SimEventKind::kGrasped:
      return "grasped";
    case SimEventKind::kReleased:
      return "released";
    case SimEventKind::kLost:
      return "lost";
  }
  return "unknown";
}

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
