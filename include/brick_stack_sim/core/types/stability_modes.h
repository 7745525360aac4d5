#pragma once

#include <string>
#include <vector>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// The stability modes this build has, from its registry, in the order
/// benchmarks and tests list them: "none" (plain Bullet) first.
const std::vector<std::string>& availableStabilityModes();

/// One line on what `mode` does; empty for an unknown mode.
std::string describeStabilityMode(const std::string& mode);

/// Success when `mode` is available; otherwise the message names it and
/// lists what is ("stability mode 'magic' is not available in this build
/// (available: none, com)").
Status checkStabilityMode(const std::string& mode);

}  // namespace brick_stack_sim
