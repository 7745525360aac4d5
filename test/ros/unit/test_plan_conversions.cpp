// ~simulate_plan without a master: a request becomes a Plan only when every
// field is sound (a refusal names the field), the defaults of duration and
// fall_distance, pushes at a brick's centre, nothing non-finite in the
// answer, and the parameter ~max_concurrent_plans.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/ros/interface_names.h"
#include "brick_stack_sim/ros/node_options.h"
#include "brick_stack_sim/ros/plan_conversions.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

PlanStep placeMsg(double at, const std::string& id, double x, double z) {
  PlanStep step;
  step.action = PlanStep::PLACE;
  step.at = at;
  step.id = id;
  step.pose.position.x = x;
  step.pose.position.z = z;
  step.pose.orientation.w = 1.0;
  return step;
}

PlanStep actionMsg(std::uint8_t action, double at, const std::string& id = "") {
  PlanStep step;  // the pose is all zero, as a planner leaves an unused one
  step.action = action;
  step.at = at;
  step.id = id;
  return step;
}

SimulatePlan::Request fourSteps() {
  SimulatePlan::Request request;
  request.steps = {placeMsg(0.0, "a", 0.0, 0.0039), placeMsg(0.5, "b", 0.2, 0.0039),
                   actionMsg(PlanStep::REMOVE, 1.0, "a"), actionMsg(PlanStep::WAIT, 1.5)};
  return request;
}

/// Expects `request` refused with a message holding `field`.
void expectRefused(const SimulatePlan::Request& request, const std::string& field) {
  Plan plan;
  plan.duration = 123.0;  // a marker: a refusal leaves the plan alone
  const Status status = fromMsg(request, &plan);
  EXPECT_FALSE(status.ok) << field << ": accepted";
  EXPECT_NE(status.message.find(field), std::string::npos) << status.message;
  EXPECT_EQ(plan.duration, 123.0);
}

TEST(PlanConversions, ASoundRequestBecomesThePlanWithItsDefaults) {
  Plan plan;
  const Status status = fromMsg(fourSteps(), &plan);
  ASSERT_TRUE(status.ok) << status.message;
  ASSERT_EQ(plan.steps.size(), 4u);
  EXPECT_EQ(plan.steps[0].action, PlannedStep::Action::kPlace);
  EXPECT_EQ(plan.steps[0].placement.id, "a");
  EXPECT_EQ(plan.steps[1].placement.pose.translation().x(), 0.2);
  EXPECT_EQ(plan.steps[2].action, PlannedStep::Action::kRemove);
  EXPECT_EQ(plan.steps[2].id, "a");
  EXPECT_EQ(plan.steps[3].action, PlannedStep::Action::kWait);
  // duration 0: the last step's time + 2 s; fall_distance 0: 1 cm.
  EXPECT_EQ(plan.duration, 1.5 + kDefaultPlanSettleTime);
  EXPECT_EQ(plan.fall_distance, 0.01);

  SimulatePlan::Request given = fourSteps();
  given.duration = 4.0;
  given.fall_distance = 0.002;
  ASSERT_TRUE(fromMsg(given, &plan).ok);
  EXPECT_EQ(plan.duration, 4.0);
  EXPECT_EQ(plan.fall_distance, 0.002);
  // No steps at all: the world as it is, for 2 s.
  ASSERT_TRUE(fromMsg(SimulatePlan::Request(), &plan).ok);
  EXPECT_TRUE(plan.steps.empty());
  EXPECT_EQ(plan.duration, kDefaultPlanSettleTime);
}

TEST(PlanConversions, EveryBadFieldIsRefusedByName) {
  SimulatePlan::Request request = fourSteps();
  request.steps[1].pose.position.y = kNaN;
  expectRefused(request, "steps[1].pose.position.y is nan");
  request = fourSteps();
  request.steps[0].pose.orientation.w = 2.0;
  expectRefused(request, "steps[0].pose.orientation has norm 2");
  request = fourSteps();
  request.steps[0].pose.orientation.w = 0.0;
  expectRefused(request, "steps[0].pose.orientation");
  request = fourSteps();
  request.steps[1].twist.angular.z = kInf;
  expectRefused(request, "steps[1].twist.angular.z");
  // In a field the action does not use, too.
  request = fourSteps();
  request.steps[3].impulse.x = kNaN;
  expectRefused(request, "steps[3].impulse.x");
  request = fourSteps();
  request.steps[2].pose.orientation.x = -kInf;
  expectRefused(request, "steps[2].pose.orientation.x");
  request = fourSteps();
  request.steps.push_back(actionMsg(PlanStep::PUSH, 2.0, "b"));
  request.steps.back().point.z = kNaN;
  expectRefused(request, "steps[4].point.z");
  request = fourSteps();
  request.steps[2].action = 4;
  expectRefused(request, "steps[2].action = 4");
  request = fourSteps();
  request.steps[1].at = kNaN;
  expectRefused(request, "steps[1].at is nan");
  request = fourSteps();
  request.steps[1].at = -0.5;
  expectRefused(request, "steps[1].at");
  // Out of order: the core names the step from 1.
  request = fourSteps();
  request.steps[3].at = 0.2;
  expectRefused(request, "step 4");
  for (double duration : {kNaN, -1.0, 1.0, 1e9}) {
    request = fourSteps();
    request.duration = duration;
    expectRefused(request, "duration");
  }
  for (double distance : {kNaN, kInf, -0.01}) {
    request = fourSteps();
    request.fall_distance = distance;
    expectRefused(request, "fall_distance");
  }
  request = SimulatePlan::Request();
  request.steps.assign(kMaxPlanSteps + 1, actionMsg(PlanStep::WAIT, 0.0));
  expectRefused(request, "more than 10000");
  request.steps.pop_back();
  Plan plan;
  EXPECT_TRUE(fromMsg(request, &plan).ok) << "exactly the most steps are refused";
}

TEST(PlanConversions, TheAnswerHoldsNothingNonFinite) {
  PlanOutcome outcome;
  outcome.bricks.resize(3);
  outcome.bricks[0].brick.id = "fine";
  outcome.bricks[0].displacement = 0.02;
  outcome.bricks[0].fell = true;
  outcome.bricks[1].brick.id = "nan_pose";
  outcome.bricks[1].brick.pose.translation().x() = kNaN;
  outcome.bricks[2].brick.id = "nan_displacement";
  outcome.bricks[2].displacement = kNaN;
  outcome.lost = {"gone"};
  outcome.fallen = 2;
  outcome.verdict = "2 brick(s) fell, among them fine";
  outcome.sim_time = 1.5;
  SimEvent event;
  event.time = 12.25;
  event.kind = SimEventKind::kLost;
  event.brick_id = "gone";
  outcome.events = {event};
  event.time = kNaN;
  outcome.events.push_back(event);
  SimulatePlan::Response response;
  std::size_t left_out = 0;
  toMsg(outcome, "world", &response, &left_out);
  EXPECT_EQ(left_out, 2u);
  ASSERT_EQ(response.bricks.size(), 1u);
  EXPECT_EQ(response.bricks[0].brick.id, "fine");
  EXPECT_EQ(response.bricks[0].displacement, 0.02);
  EXPECT_TRUE(response.bricks[0].fell);
  EXPECT_EQ(response.lost, std::vector<std::string>{"gone"});
  EXPECT_EQ(response.fallen, 2u);
  EXPECT_FALSE(response.stands);
  EXPECT_EQ(response.sim_time, 1.5);
  ASSERT_EQ(response.events.size(), 2u);
  EXPECT_EQ(response.events[0].kind, StabilityEvent::LOST);
  EXPECT_EQ(response.events[0].header.stamp.toSec(), 12.25);
  EXPECT_EQ(response.events[0].header.frame_id, "world");
  EXPECT_EQ(response.events[1].header.stamp.toSec(), 0.0);
}

Status loadPlans(const ParameterValue& value, NodeOptions* options) {
  ParameterValue tree;
  tree.set(kMaxConcurrentPlansParameter, value);
  return loadNodeOptions(tree, options);
}

TEST(PlanParameter, MaxConcurrentPlansIsReadAndChecked) {
  NodeOptions options;
  ASSERT_TRUE(loadNodeOptions(ParameterValue(), &options).ok);
  EXPECT_EQ(options.max_concurrent_plans, 2);
  ASSERT_TRUE(loadPlans(ParameterValue::makeInt(64), &options).ok);
  EXPECT_EQ(options.max_concurrent_plans, 64);
  for (const ParameterValue& bad :
       {ParameterValue::makeInt(0), ParameterValue::makeInt(65), ParameterValue::makeInt(-1),
        ParameterValue::makeDouble(2.0), ParameterValue::makeString("2")}) {
    NodeOptions refused;
    refused.max_concurrent_plans = 7;
    const Status status = loadPlans(bad, &refused);
    EXPECT_FALSE(status.ok) << bad.describe();
    EXPECT_NE(status.message.find("~max_concurrent_plans"), std::string::npos) << status.message;
    EXPECT_EQ(refused.max_concurrent_plans, 7) << "a refused load changed the options";
  }
  // A typo of another key still names the known ones, this one among them.
  ParameterValue typo;
  typo.set("max_concurent_plans", ParameterValue::makeInt(3));
  const Status status = loadNodeOptions(typo, &options);
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("max_concurrent_plans"), std::string::npos) << status.message;
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
