#pragma once

#include <Eigen/Core>

#include "brick_stack_sim/core/stability/stability_mode.h"
#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// The table: a static box whose top face is the plane z = 0, centred on the
/// world origin, standing `height` above a floor that catches what falls off.
struct TableOptions {
  Eigen::Vector2d size{1.2, 0.8};  ///< Top face x, y [m].
  double thickness = 0.03;         ///< [m]
  double height = 0.75;            ///< Table top above the floor [m].
  double friction = 0.5;           ///< Coulomb coefficient against bricks [-].
  double restitution = 0.0;        ///< [-]
};

/// Thresholds of the stack stability layer (mode com); config/stability.yaml.
struct StabilityOptions {
  /// A brick slower than both of these for `rest_time` is at rest and may
  /// join the stack (thesis 3.3.2). Bullet's own resting jitter at 1 ms steps
  /// is well below them; a brick still settling after a drop is above.
  double rest_linear_speed = 0.005;  ///< [m/s]
  double rest_angular_speed = 0.05;  ///< [rad/s]
  double rest_time = 0.02;           ///< [s]
  /// Contacts closing faster than this are impacts, not support (thesis 3.3.1) [m/s].
  double impact_speed = 0.05;
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

/// Everything that shapes the simulation of a world. The defaults are chosen
/// for KAPLA-sized bricks (8 mm thick); see brick_world.cpp for why.
struct WorldOptions {
  StabilityMode mode = StabilityMode::kNone;
  double time_step = 1.0 / 1000.0;  ///< Fixed step [s].
  int solver_iterations = 20;       ///< Sequential-impulse iterations per step.
  double gravity = 9.81;            ///< Magnitude [m/s^2], pointing to -z.

  /// Bullet's own deactivation. Bullet's defaults (0.8 m/s, 1 rad/s) would put
  /// a slowly tipping brick to sleep; these are scaled to an 8 mm brick.
  bool sleeping = true;
  double linear_sleep_threshold = 0.005;  ///< [m/s]
  double angular_sleep_threshold = 0.05;  ///< [rad/s]
  double deactivation_time = 2.0;         ///< Time below both thresholds before sleeping [s].

  /// Split impulse: position errors deeper than this are corrected without
  /// adding velocity [m]. Bullet's -0.04 m is five brick thicknesses.
  double split_impulse_penetration_threshold = -0.0004;
  double erp = 0.2;                ///< Error reduction per step for contacts [-].
  double collision_margin = 1e-4;  ///< Box collision margin [m], inside the box.

  /// A placement that would sink this deep into another brick is refused [m].
  double overlap_tolerance = 1e-4;
  /// A brick whose centre drops this far below the table top has fallen off [m].
  double fall_off_depth = 0.02;
  /// Placement speeds above these are refused as unphysical.
  double max_linear_speed = 50.0;    ///< [m/s]
  double max_angular_speed = 500.0;  ///< [rad/s]

  TableOptions table;
  StabilityOptions stability;
};

/// Checks every field; the message names the first bad one and its value.
Status validate(const WorldOptions& options);

}  // namespace brick_stack_sim
