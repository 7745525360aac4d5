#pragma once

#include <string>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// The stability model that runs on top of Bullet (parameter `stability/mode`).
enum class StabilityMode {
  kNone,         ///< Plain Bullet: the baseline.
  kCom,          ///< The thesis's COM-above / support hull model.
  kEquilibrium,  ///< Rigid-block static equilibrium as a linear program.
};

const char* toString(StabilityMode mode);
/// Parses "none", "com" or "equilibrium".
Status parseStabilityMode(const std::string& text, StabilityMode* mode);
/// Whether this build implements `mode`; the error says what is available.
Status checkStabilityModeAvailable(StabilityMode mode);

}  // namespace brick_stack_sim
