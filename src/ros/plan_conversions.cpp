// ~simulate_plan's request into a Plan and its outcome into the response:
// every field checked on the way in by the conversions the other services
// use, nothing non-finite on the way out.
#include "brick_stack_sim/ros/plan_conversions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

/// NaN or Inf anywhere in a step is refused, in the fields its action uses
/// or not: a planner that sends one has a bug worth hearing about. (Only a
/// PLACE's quaternion must be a rotation: a WAIT's unused pose is all zero.)
Status checkAllFinite(const PlanStep& msg, const std::string& field) {
  Eigen::Vector3d unused;
  if (Status s = fromMsg(msg.pose.position, field + ".pose.position", &unused); !s) return s;
  const geometry_msgs::Quaternion& q = msg.pose.orientation;
  for (const auto& [name, value] :
       {std::pair<const char*, double>{"x", q.x}, {"y", q.y}, {"z", q.z}, {"w", q.w}})
    if (!std::isfinite(value)) return notFinite(field + ".pose.orientation." + name, value);
  Eigen::Vector3d linear, angular;
  if (Status s = fromMsg(msg.twist, field + ".twist", &linear, &angular); !s) return s;
  if (Status s = fromMsg(msg.impulse, field + ".impulse", &unused); !s) return s;
  return fromMsg(msg.point, field + ".point", &unused);
}

/// One step of the request, `field` its name ("steps[3]"), checked whole.
Status stepFromMsg(const PlanStep& msg, const std::string& field, PlannedStep* step) {
  PlannedStep result;
  if (msg.action > PlanStep::WAIT)
    return Status::error(field + ".action = " + std::to_string(msg.action) +
                         ": must be PLACE 0, REMOVE 1, PUSH 2 or WAIT 3");
  result.action = static_cast<PlannedStep::Action>(msg.action);
  if (!std::isfinite(msg.at)) return notFinite(field + ".at", msg.at);
  if (msg.at < 0.0)
    return Status::error(field + ".at = " + std::to_string(msg.at) +
                         ": must be >= 0 (seconds after the plan starts)");
  if (Status finite = checkAllFinite(msg, field); !finite) return finite;
  result.at = msg.at;
  result.id = msg.id;
  switch (msg.action) {
    case PlanStep::PLACE:
      result.placement.id = msg.id;
      result.placement.type = msg.type;
      if (Status s = fromMsg(msg.pose, field + ".pose", &result.placement.pose); !s) return s;
      if (Status s = fromMsg(msg.twist, field + ".twist", &result.placement.linear_velocity,
                             &result.placement.angular_velocity);
          !s)
        return s;
      break;
    case PlanStep::PUSH:
      if (Status s = fromMsg(msg.impulse, field + ".impulse", &result.impulse); !s) return s;
      if (Status s = fromMsg(msg.point, field + ".point", &result.point); !s) return s;
      break;
    default:
      break;
  }
  *step = std::move(result);
  return Status::success();
}

/// ros::Time of a sim time [s] when it is one (finite, in its range); else 0.
ros::Time stampOf(double t) {
  if (!std::isfinite(t) || t < 0.0 || t > static_cast<double>(std::numeric_limits<int32_t>::max()))
    return ros::Time();
  return ros::Time(t);
}

/// A count for a uint32 field, clamped rather than wrapped.
std::uint32_t count32(std::size_t n) {
  return static_cast<std::uint32_t>(
      std::min<std::size_t>(n, std::numeric_limits<std::uint32_t>::max()));
}

}  // namespace

Status fromMsg(const SimulatePlan::Request& request, Plan* plan) {
  if (request.steps.size() > kMaxPlanSteps)
    return Status::error("steps has " + std::to_string(request.steps.size()) +
                         " entries, more than " + std::to_string(kMaxPlanSteps) +
                         " in one request");
  Plan result;
  result.steps.resize(request.steps.size());
  for (std::size_t i = 0; i < request.steps.size(); ++i)
    if (Status s =
            stepFromMsg(request.steps[i], "steps[" + std::to_string(i) + "]", &result.steps[i]);
        !s)
      return s;
  if (!std::isfinite(request.duration)) return notFinite("duration", request.duration);
  if (request.duration < 0.0)
    return Status::error("duration = " + std::to_string(request.duration) +
                         ": must be >= 0 s (0: the last step's time + 2 s)");
  if (!std::isfinite(request.fall_distance))
    return notFinite("fall_distance", request.fall_distance);
  if (request.fall_distance < 0.0)
    return Status::error("fall_distance = " + std::to_string(request.fall_distance) +
                         ": must be >= 0 m (0: 0.01 m)");
  const double last = result.steps.empty() ? 0.0 : result.steps.back().at;
  result.duration = request.duration > 0.0 ? request.duration : last + kDefaultPlanSettleTime;
  result.fall_distance = request.fall_distance > 0.0 ? request.fall_distance : kDefaultFallDistance;
  // Times in order, within the longest plan; the duration after the last step.
  if (Status valid = checkPlan(result); !valid) return valid;
  *plan = std::move(result);
  return Status::success();
}

void toMsg(const PlanOutcome& outcome, const std::string& frame_id,
           SimulatePlan::Response* response, std::size_t* left_out) {
  response->stands = outcome.stands;
  response->verdict = outcome.verdict;
  response->fallen = count32(outcome.fallen);
  response->moving = count32(outcome.moving);
  response->sim_time = std::isfinite(outcome.sim_time) ? outcome.sim_time : 0.0;
  response->bricks.reserve(outcome.bricks.size());
  for (const PlanBrickOutcome& brick : outcome.bricks) {
    PlanBrick msg;
    if (!toMsg(brick.brick, &msg.brick).ok || !std::isfinite(brick.displacement)) {
      ++*left_out;
      continue;
    }
    msg.displacement = brick.displacement;
    msg.fell = brick.fell;
    response->bricks.push_back(std::move(msg));
  }
  response->lost = outcome.lost;
  response->events.reserve(outcome.events.size());
  for (const SimEvent& event : outcome.events) {
    StabilityEvent msg = toMsg(event);
    // The plan's own clock (the copy's, which starts at the live one): when
    // it happened in the plan, whatever clock the node stamps ~events with.
    msg.header.stamp = stampOf(event.time);
    msg.header.frame_id = frame_id;
    response->events.push_back(std::move(msg));
  }
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
