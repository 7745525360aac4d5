#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "brick_stack_sim/core/simulation/plan.h"
#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

std::string seconds(double value) { return formatNumber(value) + " s"; }

const char* actionName(PlannedStep::Action action) {
  switch (action) {
    case PlannedStep::Action::kPlace:
      return "place";
    case PlannedStep::Action::kRemove:
      return "remove";
    case PlannedStep::Action::kPush:
      return "push";
    case PlannedStep::Action::kWait:
      return "wait";
  }
  return "?";
}

/// "step 3 (remove 'b2' at 0.500 s)": how a refusal names the step.
std::string stepName(const Plan& plan, std::size_t index) {
  const PlannedStep& step = plan.steps[index];
  const std::string& id = step.action == PlannedStep::Action::kPlace ? step.placement.id : step.id;
  return "step " + std::to_string(index + 1) + " (" + actionName(step.action) +
         (id.empty() ? "" : " " + quotedId(id)) + " at " + seconds(step.at) + ")";
}

/// Steps of `dt` from the plan's start until `at` has come [s].
std::uint64_t stepsUntil(double at, double dt) {
  // A time that is a whole number of steps, give or take rounding, is that step.
  return static_cast<std::uint64_t>(std::ceil(at / dt - 1e-9));
}

/// Where a brick was when the plan started, or where the plan placed it.
struct StartOf {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  bool fell_off = false;  ///< Already on the floor then.
};
using Start = std::map<std::string, StartOf>;

/// Applies one step to `world`; a placement's brick starts where placed.
Status applyStep(const PlannedStep& step, bool more_at_this_instant, BrickWorld* world,
                 Start* start) {
  switch (step.action) {
    case PlannedStep::Action::kPlace: {
      std::string id;
      const Status placed = world->addBrick(step.placement, &id, more_at_this_instant);
      if (placed) (*start)[id] = {step.placement.pose, false};
      return placed;
    }
    case PlannedStep::Action::kRemove:
      return world->removeBrick(step.id);
    case PlannedStep::Action::kPush: {
      BrickSnapshot brick;
      const bool centre = step.point.isZero() && world->find(step.id, &brick);
      return world->applyImpulse(step.id, step.impulse,
                                 centre ? Eigen::Vector3d(brick.pose.translation()) : step.point);
    }
    case PlannedStep::Action::kWait:
      break;
  }
  return Status::success();
}

/// The bricks at the end of a plan against where they started, and the
/// verdict, into `result` (its events already taken).
void summarize(const Plan& plan, const Start& start, const BrickWorld& world,
               PlanOutcome* outcome) {
  PlanOutcome& result = *outcome;
  std::string first_fallen;
  for (const SimEvent& event : result.events) {
    if (event.kind != SimEventKind::kLost) continue;
    result.lost.push_back(event.brick_id);
    if (first_fallen.empty()) first_fallen = event.brick_id + " (left the world)";
  }
  for (BrickSnapshot& brick : world.snapshot()) {
    PlanBrickOutcome outcome_of;
    const StartOf& from = start.at(brick.id);
    outcome_of.displacement = (brick.pose.translation() - from.pose.translation()).norm();
    const double turn =
        Eigen::AngleAxisd(from.pose.linear().transpose() * brick.pose.linear()).angle();
    outcome_of.fell = (brick.fell_off && !from.fell_off) ||
                      outcome_of.displacement > plan.fall_distance || turn > plan.fall_angle;
    if (outcome_of.fell && first_fallen.empty()) first_fallen = brick.id;
    result.fallen += outcome_of.fell;
    result.moving += brick.state == BrickState::kDynamic;
    outcome_of.brick = std::move(brick);
    result.bricks.push_back(std::move(outcome_of));
  }
  result.fallen += result.lost.size();
  result.stands = result.fallen == 0;
  result.verdict =
      result.stands
          ? "stands: no brick moved more than " + millimetres(plan.fall_distance) +
                " or turned more than " + formatNumber(plan.fall_angle) + " rad" +
                (result.moving ? ", " + std::to_string(result.moving) + " still moving" : "")
          : std::to_string(result.fallen) + " brick(s) fell, among them " + first_fallen;
}

}  // namespace

Status checkPlan(const Plan& plan) {
  double last = 0.0;
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    const double at = plan.steps[i].at;
    if (!std::isfinite(at) || at < 0.0)
      return Status::error("step " + std::to_string(i + 1) + ": its time must be finite and >= 0");
    if (at < last)
      return Status::error("step " + std::to_string(i + 1) + ": its time " + seconds(at) +
                           " comes before the step before it (" + seconds(last) +
                           "): steps must be in time order");
    if (at > kMaxPlanDuration)
      return Status::error("step " + std::to_string(i + 1) + ": its time " + seconds(at) +
                           " is past the longest plan, " + seconds(kMaxPlanDuration));
    last = at;
  }
  if (!std::isfinite(plan.duration) || plan.duration < last || plan.duration > kMaxPlanDuration)
    return Status::error("duration must be finite, at least the last step's time (" +
                         seconds(last) + ") and at most " + seconds(kMaxPlanDuration));
  if (!std::isfinite(plan.fall_distance) || !(plan.fall_distance > 0.0))
    return Status::error("fall distance must be finite and > 0 m");
  if (!std::isfinite(plan.fall_angle) || !(plan.fall_angle > 0.0))
    return Status::error("fall angle must be finite and > 0 rad");
  return Status::success();
}

Status runPlan(const Plan& plan, BrickWorld* world, PlanOutcome* outcome,
               const std::atomic<bool>* stop) {
  if (Status valid = checkPlan(plan); !valid) return valid;
  world->takeEvents();
  const double dt = world->options().time_step;
  Start start;
  for (const BrickSnapshot& brick : world->snapshot())
    start[brick.id] = {brick.pose, brick.fell_off};
  std::uint64_t done = 0;
  const auto stepUntil = [&](double at) {
    for (const std::uint64_t due = stepsUntil(at, dt); done < due; ++done) {
      if (stop && stop->load()) return false;
      world->step();
    }
    return true;
  };
  const Status stopped = Status::error("stopped before its end: the simulation is shutting down");
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    if (!stepUntil(plan.steps[i].at)) return stopped;
    // Placements at one instant are judged as one structure.
    const bool more_at_this_instant = i + 1 < plan.steps.size() &&
                                      plan.steps[i + 1].action == PlannedStep::Action::kPlace &&
                                      stepsUntil(plan.steps[i + 1].at, dt) == done;
    if (Status applied = applyStep(plan.steps[i], more_at_this_instant, world, &start); !applied)
      return Status::error(stepName(plan, i) + ": " + applied.message);
  }
  world->judgePlacements();
  if (!stepUntil(plan.duration)) return stopped;
  PlanOutcome result;
  result.sim_time = static_cast<double>(done) * dt;
  result.events = world->takeEvents();
  summarize(plan, start, *world, &result);
  *outcome = std::move(result);
  return Status::success();
}

}  // namespace brick_stack_sim
