#pragma once

#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/geometry/polygon2d.h"

namespace brick_stack_sim {

/// What one supporter receives from the brick above: a vertical load, as the
/// mass that would weigh as much [kg], acting at `point` in the contact patch.
struct LoadShare {
  double mass = 0.0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  /// Height of the centre of mass of what passes this share down [m]: it
  /// places the COM-above in 3D (thesis figure 5), not where the load acts.
  double height = 0.0;
};

/// How the load was split (tests check that each rule is reached).
enum class LoadSplitRule {
  kSingleSupporter,  ///< One patch: all of it at the load's projection.
  kLeverRule,        ///< Two patches: lever rule between the patch centres.
  kLeastNorm,        ///< Three or more: shares closest to equal that balance the moment.
  kOnePatchCarries,  ///< The load's projection lies in one patch, which carries it all.
  kHullTriangle,     ///< Fallback: barycentric split over a triangle of patch corners.
  kUnsupported,      ///< The load's projection is outside every patch combination.
};

/// Splits a load `mass` [kg] whose line of action passes through `point`
/// among the support `patches` (one share per patch, in the same order) so
/// that force and moment balance hold: the shares add up to `mass`, their
/// moments about any vertical axis add up to the load's, and every share acts
/// inside its own patch. This is the fix of the thesis's equation 10, which
/// put the upper brick's COM-above into the supporter and could tip a plain
/// 4-stack: a load acts where it is transmitted. Returns kUnsupported (and
/// empty shares) when `point` is not inside the combined hull.
LoadSplitRule distributeLoad(double mass, const Eigen::Vector2d& point,
                             const std::vector<Polygon2d>& patches, std::vector<LoadShare>* shares);

}  // namespace brick_stack_sim
