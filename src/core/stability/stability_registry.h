#pragma once

#include <memory>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "stability/stability_model.h"

namespace brick_stack_sim {

/// The model `options.mode` names, or null for "none" (plain Bullet: no
/// model at all, so nothing of the layer costs anything). `options` must
/// have been validated. `name_of` words the bodies in the model's reasons.
std::unique_ptr<StabilityModel> createStabilityModel(const StabilityOptions& options,
                                                     BodyNamer name_of);

}  // namespace brick_stack_sim
