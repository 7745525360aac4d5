#pragma once

#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/sim_event.h"
#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {

/// One step of a plan, applied `at` seconds after the plan starts. (Not
/// `PlanStep`: that is PlanStep.msg's type, in this namespace too.)
struct PlannedStep {
  enum class Action : unsigned char {
    kPlace,   ///< addBrick(placement)
    kRemove,  ///< removeBrick(id)
    kPush,    ///< applyImpulse(id, impulse, point)
    kWait,    ///< nothing: the plan runs at least until `at`
  };
  Action action = Action::kWait;
  double at = 0.0;           ///< [s] after the plan starts; steps in non-decreasing order.
  BrickPlacement placement;  ///< kPlace.
  std::string id;            ///< kRemove, kPush: the brick.
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();  ///< kPush [N s], frame world.
  /// kPush: where [m], frame world; all zero: the brick's centre where it
  /// is when the step is applied.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// When a brick has fallen, in plans and in the batch runner's reports: once
/// its centre is farther than this from where it was laid [m], a centimetre,
/// far beyond what a brick that stays where it was laid ever drifts
/// (micrometres).
constexpr double kDefaultFallDistance = 0.01;
/// Or once it has turned farther than this [rad], about 6 degrees: a plank
/// that tips off the one below turns by about its thickness over its half
/// length (8 degrees for KAPLA) while its centre drops less than a centimetre.
constexpr double kDefaultFallAngle = 0.1;

/// A sequence of steps and how long to simulate.
struct Plan {
  std::vector<PlannedStep> steps;
  /// Simulated after the plan starts [s]: at least the last step's `at`.
  double duration = 0.0;
  /// A brick has fallen when it ends farther than this from where it was
  /// when the plan started, or from where the plan placed it [m].
  double fall_distance = kDefaultFallDistance;
  /// Or when it has turned farther than this from how it started [rad]: a
  /// plank that tips off the one below may end less than a centimetre away.
  double fall_angle = kDefaultFallAngle;
};

/// The most a plan may simulate [s]: its duration is checked against it.
constexpr double kMaxPlanDuration = 3600.0;

/// A brick at the end of a plan.
struct PlanBrickOutcome {
  BrickSnapshot brick;
  /// From where it was when the plan started, or where the plan placed it [m].
  double displacement = 0.0;
  /// Moved more than Plan::fall_distance, turned more than Plan::fall_angle,
  /// or fell off the table during the plan (one already on the floor when it
  /// started has not fallen again by lying there).
  bool fell = false;
};

/// What a plan did.
struct PlanOutcome {
  std::vector<PlanBrickOutcome> bricks;  ///< Every brick at the end, in placement order.
  std::vector<std::string> lost;         ///< Bricks that left the world box (removed).
  std::vector<SimEvent> events;          ///< Of the plan, oldest first.
  std::size_t fallen = 0;                ///< Bricks that fell, the lost ones included.
  std::size_t moving = 0;                ///< Bricks not frozen at the end.
  /// Nothing fell and nothing was lost.
  bool stands = false;
  std::string verdict;    ///< In words: what fell first, or that it stands.
  double sim_time = 0.0;  ///< Simulated [s].
};

/// Whether `plan` can be run as written: finite times in order from 0, a
/// duration from the last step's time up to kMaxPlanDuration, a positive
/// fall distance and angle. What each step does is checked when it is applied.
Status checkPlan(const Plan& plan);

/// Runs `plan` on `world` from its present time: each step when its time
/// comes (steps at one instant placed together, as addBricks() does), then
/// on to the duration. A step the world refuses ends the run with an error
/// naming it; `world` is then part way through the plan, so run plans on a
/// copy (BrickWorld::copy()). Takes the world's pending events first.
/// `stop` (optional), once set, ends the run at the next step with an error
/// (a node that shuts down does not wait for an hour of sim time).
Status runPlan(const Plan& plan, BrickWorld* world, PlanOutcome* outcome,
               const std::atomic<bool>* stop = nullptr);

}  // namespace brick_stack_sim
