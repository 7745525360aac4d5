// The words the core uses for its enums in reports, logs and parameters.
#include "brick_stack_sim/core/brick.h"
#include "brick_stack_sim/core/sim_event.h"
#include "brick_stack_sim/core/stability/stability_mode.h"

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
  }
  return "unknown";
}

const char* toString(StabilityMode mode) {
  switch (mode) {
    case StabilityMode::kNone:
      return "none";
    case StabilityMode::kCom:
      return "com";
    case StabilityMode::kEquilibrium:
      return "equilibrium";
  }
  return "unknown";
}

Status parseStabilityMode(const std::string& text, StabilityMode* mode) {
  for (StabilityMode candidate :
       {StabilityMode::kNone, StabilityMode::kCom, StabilityMode::kEquilibrium}) {
    if (text == toString(candidate)) {
      *mode = candidate;
      return Status::success();
    }
  }
  return Status::error("unknown stability mode '" + text + "' (expected none, com or equilibrium)");
}

Status checkStabilityModeAvailable(StabilityMode mode) {
  if (mode == StabilityMode::kNone || mode == StabilityMode::kCom) return Status::success();
  return Status::error(std::string("stability mode '") + toString(mode) +
                       "' is not available in this version; available: none, com");
}

}  // namespace brick_stack_sim
