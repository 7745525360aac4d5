// The stability modes a parameterised suite runs in, asked of the registry so
// that a new model is tested by every suite without a line in any of them.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "stability/stability_registry.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace test {

/// Every mode of the registry, "none" (plain Bullet) first.
inline const std::vector<std::string>& allModes() { return availableStabilityModes(); }

/// The modes that run a stability model: all but plain Bullet. Suites whose
/// expectations come from statics run in these.
inline std::vector<std::string> modelModes() {
  std::vector<std::string> modes;
  for (const std::string& mode : availableStabilityModes()) {
    if (createStabilityModel(optionsFor(mode).stability, [](BodyHandle) { return ""; }))
      modes.push_back(mode);
  }
  return modes;
}

/// Names a parameterised test by its mode ("Modes/HeldBrick.Grasp/com").
inline std::string modeName(const ::testing::TestParamInfo<std::string>& info) {
  return info.param;
}

}  // namespace test
}  // namespace brick_stack_sim
