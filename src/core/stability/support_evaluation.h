#pragma once

#include <Eigen/Core>

#include "stability/stability_model.h"

namespace brick_stack_sim {

/// Fills the hulls and heights of the patches of `stability->supports`, the
/// combined hull and its height, and measures `load_point` (the COM-above)
/// against the combined hull: `com_above` and `margin` [m], 0 when nothing
/// supports the brick (there is no hull to measure against).
void evaluateSupport(const Eigen::Vector3d& load_point, BrickStability* stability);

/// Everything `stability` touches, from below or beside, once each, in handle order.
std::vector<BodyHandle> supportersOf(const BrickStability& stability);

}  // namespace brick_stack_sim
