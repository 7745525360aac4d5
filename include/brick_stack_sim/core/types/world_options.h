#pragma once

#include <string>

#include <Eigen/Core>

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/stability_options.h"

namespace brick_stack_sim {

/// The table: a static box whose top face is the plane z = 0, centred on the
/// world origin, standing `height` above a floor that catches what falls off
/// (parameters `table/...`).
struct TableOptions {
  Eigen::Vector2d size{1.2, 0.8};  ///< Top face x, y [m].
  double thickness = 0.03;         ///< [m]
  double height = 0.75;            ///< Table top above the floor [m].
  double friction = 0.5;           ///< Coulomb coefficient against bricks [-].
  double restitution = 0.0;        ///< [-]
};

/// Bullet's own deactivation of resting bodies (parameters `sleeping/...`).
/// Bullet's defaults (0.8 m/s, 1 rad/s) would put a slowly tipping brick to
/// sleep; these are scaled to an 8 mm brick.
struct SleepingOptions {
  bool enabled = true;              ///< Off only for baselines.
  double linear_threshold = 0.005;  ///< [m/s]
  double angular_threshold = 0.05;  ///< [rad/s]
  double time = 2.0;                ///< Time below both thresholds before sleeping [s].
};

/// A brick held by a teleop or planner (parameters `held/...`): it moves
/// toward its target no faster than these, so a target far away is a sweep,
/// not a teleport, and what it strikes is judged as an impact.
struct HeldOptions {
  double max_linear_speed = 0.5;   ///< [m/s]
  double max_angular_speed = 3.0;  ///< [rad/s]
  /// The hand is a spring to its target: stopped by a frozen brick short of
  /// a target beyond it, it presses on that brick with this times how far
  /// the target lies beyond [N/m]. 0: it only stops there.
  double stiffness = 50.0;
  double max_force = 5.0;  ///< The most it presses with [N].
};

/// The box a brick's centre must stay in (parameters `bounds/...`), centred
/// on the table: a placement outside is refused, and a brick that leaves it
/// is removed and reported lost. Without it a brick placed at x = 1e300
/// missed the floor and fell for ever, and one at z = 1e300 hung in the air.
/// The floor of the box lies kBelowFloor under the floor plane, so only a
/// brick that tunnelled through the floor leaves it downwards.
struct BoundsOptions {
  double horizontal = 10.0;  ///< Largest |x| and |y| of a brick's centre [m], in (table, 1e4].
  double height = 10.0;      ///< Highest centre above the table top [m], in (0, 1e4].
  static constexpr double kBelowFloor = 1.0;  ///< [m]
};

/// Everything that shapes the simulation of a world (the parameters of
/// config/sim.yaml and config/stability.yaml but the node's own). The
/// defaults are chosen for KAPLA-sized bricks (8 mm thick); the Bullet scene
/// says why next to each setting.
struct WorldOptions {
  double time_step = 1.0 / 1000.0;  ///< Fixed step [s].
  int solver_iterations = 20;       ///< Sequential-impulse iterations per step.
  double gravity = 9.81;            ///< Magnitude [m/s^2], pointing to -z.

  SleepingOptions sleeping;

  /// Split impulse: position errors deeper than this are corrected without
  /// adding velocity [m]. Bullet's -0.04 m is five brick thicknesses.
  double split_impulse_penetration_threshold = -0.0004;
  double erp = 0.2;  ///< Error reduction per step for contacts [-].
  /// Friction held to Coulomb's cone in two directions across a contact
  /// (true, the default: docs/design.md, "Bullet at brick scale"), or
  /// Bullet's own: one direction, that of the slip, along which a pile
  /// creeps (false).
  bool friction_cone = true;
  /// Every contact's normal and friction impulses carried over whole from
  /// one step to the next, and every penetration corrected by split
  /// impulse, so that no position error feeds the velocities the carried
  /// impulses start from (true; the scheme of Box2D and Jolt, which
  /// needs `friction_cone`; `split_impulse_penetration_threshold` is then
  /// ignored). false, the default: Bullet's own, the normal impulse carried
  /// at 0.85 and friction rebuilt from nothing each step (docs/design.md,
  /// "Bullet at brick scale").
  bool full_warm_start = false;
  double collision_margin = 1e-4;  ///< Box collision margin [m], inside the box.

  /// A placement that would sink this deep into another brick is refused [m].
  double overlap_tolerance = 1e-4;
  /// A brick whose centre drops this far below the table top has fallen off [m].
  double fall_off_depth = 0.02;
  /// Placement and push speeds above these are refused as unphysical. A
  /// brick Bullet drives kBlowUpFactor times faster is a diverged solver,
  /// repaired: a brick thrown at the limit, spun by what it strikes, is not.
  double max_linear_speed = 50.0;    ///< [m/s]
  double max_angular_speed = 500.0;  ///< [rad/s]
  static constexpr double kBlowUpFactor = 4.0;

  HeldOptions held;
  TableOptions table;
  BoundsOptions bounds;
  StabilityOptions stability;
};

/// Whether `centre` [m] lies in the world box of `options` (bounds and table).
bool insideWorld(const WorldOptions& options, const Eigen::Vector3d& centre);
/// The world box in words, for messages: "|x|, |y| <= 10 m, -1.75 m <= z <= 10 m
/// (parameters bounds/horizontal, bounds/height)".
std::string describeWorldBox(const WorldOptions& options);

/// Each checks every field; the message names the first bad one by its key,
/// with the module's path for the nested ones ("table/size = 0: ...").
Status validate(const TableOptions& options);
Status validate(const SleepingOptions& options);
Status validate(const HeldOptions& options);
Status validate(const BoundsOptions& options);
/// Also checks that the world box holds the table.
Status validate(const WorldOptions& options);

class OptionsReader;

/// The sections `table` and `sleeping`: their keys, checked, then validated;
/// a key they do not know is an error. `*options` changes only on success.
Status readTableOptions(OptionsReader& reader, TableOptions* options);
Status readSleepingOptions(OptionsReader& reader, SleepingOptions* options);
Status readHeldOptions(OptionsReader& reader, HeldOptions* options);
Status readBoundsOptions(OptionsReader& reader, BoundsOptions* options);
/// The world's keys at the reader's level (time_step, gravity, ...) and its
/// sections table, sleeping, held, bounds and stability. Other keys may share that level
/// (the node's): the caller, who knows them, calls reader.finish().
Status readWorldOptions(OptionsReader& reader, WorldOptions* options);

}  // namespace brick_stack_sim
