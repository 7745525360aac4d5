// The words the core uses for its enums in reports and logs.
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/sim_event.h"

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

}  // namespace brick_stack_sim
