#pragma once

#include <string>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// The stack stability layer: which model runs on top of Bullet and its
/// thresholds (parameters `stability/...`, config/stability.yaml).
struct StabilityOptions {
  /// The model, one of availableStabilityModes(): "com" (the thesis's layer)
  /// by default everywhere, since that layer is why users pick this package;
  /// "none" is plain Bullet, the baseline.
  std::string mode = "com";
  /// A brick slower than both of these for `rest_time` is at rest and may
  /// join the stack (thesis 3.3.2). Bullet's own resting jitter at 1 ms steps
  /// is well below them; a brick still settling after a drop is above.
  double rest_linear_speed = 0.005;  ///< [m/s]
  double rest_angular_speed = 0.05;  ///< [rad/s]
  double rest_time = 0.02;           ///< [s]
  /// Contacts closing faster than this are impacts, not support (thesis 3.3.1) [m/s].
  double impact_speed = 0.05;
  /// A blow on a frozen brick that would slide it less than this, and cannot
  /// tip it, is absorbed: the brick stays frozen and the striker bounces off
  /// (a gentle touch, a few cm/s, moves nothing a person could see) [m].
  double impact_min_slide = 0.0005;
  /// A contact supports only when its normal is within this angle of vertical
  /// [rad]; steeper contacts are leaning, for another model.
  double support_normal_tolerance = 0.26;
  /// Faces parallel within this angle rest flush: the patch is their whole
  /// overlap, not just the points Bullet reports [rad]. 2 mrad is 0.23 mm
  /// of height over a KAPLA length.
  double flush_angle = 0.002;
  /// Contact points farther apart than this do not touch [m].
  double contact_distance = 1e-4;
  /// Stable means: the COM-above projection lies deeper inside the support
  /// hull than this [m]. A micrometre: statics says strictly inside, and hulls
  /// of contact points along one edge, spread by rounding, are slivers a
  /// fraction of a micrometre wide that must not count as support.
  double min_margin = 1e-6;
};

/// Checks every field; the message names the first bad one by its key
/// ("rest_time = -1: must be >= 0 s").
Status validate(const StabilityOptions& options);

class OptionsReader;

/// The section `stability`: its keys, checked, then validated (thresholds
/// too in mode none, so a typo does not wait until the layer is switched on).
Status readStabilityOptions(OptionsReader& reader, StabilityOptions* options);

}  // namespace brick_stack_sim
