#pragma once
// ~simulate_plan's messages and the core's Plan / PlanOutcome: every number
// of a request is checked on the way in (the message names the field, as
// "steps[3].pose.position.x is nan"), and nothing non-finite goes out.

#include <cstddef>
#include <string>

#include "brick_stack_sim/SimulatePlan.h"
#include "brick_stack_sim/core/simulation/plan.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Most steps one ~simulate_plan may hold: a planner's sequence, not a
/// scene (a scene goes through ~reset). More are refused before anything runs.
constexpr std::size_t kMaxPlanSteps = 10000;
/// What `duration` 0 simulates after the last step [s]: long enough for a
/// plank that tips to have fallen, short enough to answer quickly.
constexpr double kDefaultPlanSettleTime = 2.0;

/// A ~simulate_plan request as a Plan, checked field by field before anything
/// runs: the step count (at most kMaxPlanSteps), each step's action (PLACE to
/// WAIT), time, pose (a unit quaternion), twist, impulse and point, the
/// duration (0: the last step's time + kDefaultPlanSettleTime) and the fall
/// distance (0: kDefaultFallDistance), then the order of the times and
/// the limits (checkPlan). The mode is not read here. A refusal names the
/// field by its index in `steps`, counted from 0 ("steps[3].pose: ..."); the
/// core's own messages count steps from 1 ("step 4 (place 'b3' at 1.5 s)").
/// `*plan` is left alone on a refusal.
Status fromMsg(const SimulatePlan::Request& request, Plan* plan);

/// Every field of `outcome` into `response` but success, message and
/// wall_time: the bricks (Brick as ~get_bricks gives it, with displacement
/// and fell), lost, the events (stamped with their sim time in the copy, in
/// `frame_id`), the counts and the verdict. A brick with a number that is not
/// finite is left out and counted in `*left_out`.
void toMsg(const PlanOutcome& outcome, const std::string& frame_id,
           SimulatePlan::Response* response, std::size_t* left_out);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
