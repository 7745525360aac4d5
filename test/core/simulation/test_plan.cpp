// Plans run on a copy of the world (BrickWorld::copy, runPlan): the copy
// goes on exactly as the live world would, the live world does not change,
// and what a plan reports agrees with statics.
#include <atomic>
#include <limits>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/simulation/plan.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"
#include "support/modes.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaThickness;
using test::placement;

constexpr int kTowerBricks = 20;  ///< 10 layers of two planks

/// A frozen two-per-layer tower at the table's centre.
std::unique_ptr<BrickWorld> frozenTower(const std::string& mode) {
  auto world = test::makeWorld(test::optionsFor(mode));
  for (int i = 0; i < kTowerBricks; ++i) EXPECT_TRUE(world->addBrick(test::towerBrick(i)).ok);
  test::runFor(world.get(), 0.1);
  world->takeEvents();
  return world;
}

PlannedStep placeStep(double at, const BrickPlacement& brick) {
  PlannedStep step;
  step.action = PlannedStep::Action::kPlace;
  step.at = at;
  step.placement = brick;
  return step;
}

PlannedStep brickStep(PlannedStep::Action action, double at, const std::string& id) {
  PlannedStep step;
  step.action = action;
  step.at = at;
  step.id = id;
  return step;
}

/// Places two planks on the tower, drops a third from 3 cm, pushes the top
/// layer and takes a brick of it away.
Plan busyPlan() {
  const double top = kTowerBricks / 2 * kKaplaThickness;
  Plan plan;
  plan.steps.push_back(placeStep(0.0, placement("p0", {0, -test::kTowerOffset, top + 0.0039})));
  plan.steps.push_back(placeStep(0.0, placement("p1", {0, test::kTowerOffset, top + 0.0039})));
  plan.steps.push_back(placeStep(0.2, placement("drop", {0, 0, top + 0.03}, M_PI / 2)));
  PlannedStep push = brickStep(PlannedStep::Action::kPush, 0.6, "p1");
  push.impulse = Eigen::Vector3d(0.0, 0.004, 0.0);
  push.point = Eigen::Vector3d(0.0, test::kTowerOffset - test::kKaplaWidth / 2, top + 0.0039);
  plan.steps.push_back(push);
  plan.steps.push_back(brickStep(PlannedStep::Action::kRemove, 0.9, "p0"));
  plan.steps.push_back(brickStep(PlannedStep::Action::kWait, 1.2, ""));
  plan.duration = 1.5;
  return plan;
}

class PlanOnCopy : public ::testing::TestWithParam<std::string> {};

TEST_P(PlanOnCopy, TheCopyRunsTheSameBitsAsTheLiveWorldWhichItLeavesAlone) {
  auto live = frozenTower(GetParam());
  ASSERT_TRUE(live->copiesExactly());
  const std::string before = test::fingerprint(*live);
  std::unique_ptr<BrickWorld> copy = live->copy();
  ASSERT_EQ(test::fingerprint(*copy), before);
  EXPECT_EQ(copy->revision(), live->revision());

  PlanOutcome on_copy;
  ASSERT_TRUE(runPlan(busyPlan(), copy.get(), &on_copy).ok);
  EXPECT_EQ(test::fingerprint(*live), before) << "a plan on the copy changed the live world";
  // The same steps on the live world: the same bits, brick by brick.
  PlanOutcome on_live;
  ASSERT_TRUE(runPlan(busyPlan(), live.get(), &on_live).ok);
  EXPECT_EQ(test::fingerprint(*live), test::fingerprint(*copy));
  ASSERT_EQ(on_copy.bricks.size(), on_live.bricks.size());
  for (std::size_t i = 0; i < on_copy.bricks.size(); ++i) {
    EXPECT_EQ(on_copy.bricks[i].displacement, on_live.bricks[i].displacement)
        << on_copy.bricks[i].brick.id;
  }
  ASSERT_EQ(on_copy.events.size(), on_live.events.size());
  for (std::size_t i = 0; i < on_copy.events.size(); ++i) {
    EXPECT_EQ(on_copy.events[i].time, on_live.events[i].time);
    EXPECT_EQ(on_copy.events[i].reason, on_live.events[i].reason);
  }
  // The plan did happen: p0 is gone, the dropped plank is there.
  EXPECT_EQ(on_copy.bricks.size(), static_cast<std::size_t>(kTowerBricks + 2));
  BrickSnapshot dropped;
  EXPECT_TRUE(copy->find("drop", &dropped));
  EXPECT_FALSE(copy->find("p0", &dropped));
}

TEST_P(PlanOnCopy, AMovingWorldIsCopiedInItsStateButNotPromisedExact) {
  auto live = frozenTower(GetParam());
  ASSERT_TRUE(live->addBrick(placement("falling", {0.3, 0.0, 0.05})).ok);
  test::runFor(live.get(), 0.01);
  EXPECT_FALSE(live->copiesExactly());
  std::unique_ptr<BrickWorld> copy = live->copy();
  EXPECT_EQ(test::fingerprint(*copy), test::fingerprint(*live));
  EXPECT_TRUE(copy->checkInvariants().ok);
}

INSTANTIATE_TEST_SUITE_P(Modes, PlanOnCopy, ::testing::ValuesIn(test::modelModes()),
                         test::modeName);

/// A plank along x on the tower's top layer (odd layers lie along y at
/// x = -/+ kTowerOffset), centred at x. By statics it stays while its
/// centre is over the outer plank it rests on: |x| < kTowerOffset + w/2.
Plan plankOnTop(double x) {
  Plan plan;
  plan.steps.push_back(
      placeStep(0.0, placement("q", {x, 0.0, (kTowerBricks / 2 + 0.5) * kKaplaThickness})));
  plan.duration = 1.0;
  return plan;
}

TEST(PlanVerdict, APlankWithinItsSupportStandsAndOneBeyondFalls) {
  const double edge = test::kTowerOffset + test::kKaplaWidth / 2;
  for (const std::string& mode : test::modelModes()) {
    auto live = frozenTower(mode);
    const std::string before = test::fingerprint(*live);
    PlanOutcome inside;
    std::unique_ptr<BrickWorld> copy = live->copy();
    ASSERT_TRUE(runPlan(plankOnTop(edge - 0.003), copy.get(), &inside).ok);
    EXPECT_TRUE(inside.stands) << mode << ": " << inside.verdict;
    EXPECT_EQ(inside.fallen, 0u);
    EXPECT_EQ(inside.moving, 0u) << mode;
    for (const PlanBrickOutcome& brick : inside.bricks)
      EXPECT_EQ(brick.displacement, 0.0) << mode << " " << brick.brick.id;

    PlanOutcome beyond;
    copy = live->copy();
    ASSERT_TRUE(runPlan(plankOnTop(edge + 0.01), copy.get(), &beyond).ok);
    EXPECT_FALSE(beyond.stands) << mode;
    EXPECT_EQ(beyond.fallen, 1u) << mode << ": " << beyond.verdict;
    EXPECT_NE(beyond.verdict.find("q"), std::string::npos) << beyond.verdict;
    EXPECT_EQ(test::fingerprint(*live), before);
  }
}

TEST(PlanVerdict, AStepTheWorldRefusesIsNamed) {
  auto world = frozenTower("com");
  Plan plan = plankOnTop(0.0);
  plan.steps.push_back(brickStep(PlannedStep::Action::kRemove, 0.5, "nope"));
  PlanOutcome outcome;
  const Status refused = runPlan(plan, world->copy().get(), &outcome);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(refused.message.find("step 2 (remove 'nope' at 0.5 s)"), std::string::npos)
      << refused.message;
  // Placed inside the tower: the overlap is named with its step.
  Plan inside;
  inside.steps.push_back(placeStep(0.0, test::towerBrick(3)));
  inside.duration = 0.1;
  const Status overlap = runPlan(inside, world->copy().get(), &outcome);
  EXPECT_FALSE(overlap.ok);
  EXPECT_NE(overlap.message.find("step 1 (place 't3'"), std::string::npos) << overlap.message;
}

TEST(PlanVerdict, ABrickAlreadyOnTheFloorHasNotFallenAgain) {
  auto world = frozenTower("com");
  // Off the table's +x edge (0.6 m): it drops to the floor before the plan.
  ASSERT_TRUE(world->addBrick(placement("off", {0.7, 0.0, 0.05})).ok);
  test::runFor(world.get(), 2.0);
  BrickSnapshot off;
  ASSERT_TRUE(world->find("off", &off));
  ASSERT_TRUE(off.fell_off);
  Plan wait;
  wait.steps.push_back(brickStep(PlannedStep::Action::kWait, 0.5, ""));
  wait.duration = 1.0;
  PlanOutcome outcome;
  ASSERT_TRUE(runPlan(wait, world->copy().get(), &outcome).ok);
  EXPECT_TRUE(outcome.stands) << outcome.verdict;
  EXPECT_EQ(outcome.fallen, 0u);
}

TEST(PlanVerdict, APushWithoutAPointPushesTheBricksCentreWhereItIsThen) {
  // A plank placed by the plan slides across its width on the table (0.5 m/s,
  // mu 0.5: 19 mm in the first 50 ms), then is pushed back at its centre
  // where it has slid to. Where it was placed now lies outside it (its half
  // width is 11.7 mm, a push point may be 1 mm out): that push would be
  // refused. Through the centre, the push turns it not at all.
  auto world = frozenTower("com");
  Plan plan;
  BrickPlacement slider = placement("slider", {0.3, 0.2, 0.5 * kKaplaThickness});
  slider.linear_velocity = Eigen::Vector3d(0.0, 0.5, 0.0);
  plan.steps.push_back(placeStep(0.0, slider));
  PlannedStep push = brickStep(PlannedStep::Action::kPush, 0.05, "slider");
  push.impulse = Eigen::Vector3d(0.0, -0.002, 0.0);
  plan.steps.push_back(push);
  plan.duration = 0.5;
  PlanOutcome outcome;
  const Status ran = runPlan(plan, world->copy().get(), &outcome);
  ASSERT_TRUE(ran.ok) << ran.message;
  bool found = false;
  for (const PlanBrickOutcome& brick : outcome.bricks) {
    if (brick.brick.id != "slider") continue;
    found = true;
    EXPECT_NEAR(Eigen::AngleAxisd(brick.brick.pose.linear()).angle(), 0.0, 1e-6);
  }
  EXPECT_TRUE(found);
}

TEST(PlanVerdict, AStopEndsARunAtItsNextStep) {
  auto world = frozenTower("com");
  Plan plan = plankOnTop(0.0);
  plan.duration = 100.0;
  const std::atomic<bool> stop{true};
  PlanOutcome outcome;
  const Status stopped = runPlan(plan, world->copy().get(), &outcome, &stop);
  EXPECT_FALSE(stopped.ok);
  EXPECT_NE(stopped.message.find("stopped"), std::string::npos) << stopped.message;
}

TEST(PlanVerdict, BadPlansAreRefusedBeforeAnythingRuns) {
  auto world = frozenTower("com");
  const std::string before = test::fingerprint(*world);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Plan> bad;
  for (double at : {nan, inf, -0.1, kMaxPlanDuration + 1.0}) {
    Plan plan = plankOnTop(0.0);
    plan.steps[0].at = at;
    plan.duration = 1.0;
    bad.push_back(plan);
  }
  Plan backwards = plankOnTop(0.0);
  backwards.steps.push_back(brickStep(PlannedStep::Action::kWait, 0.5, ""));
  backwards.steps.push_back(brickStep(PlannedStep::Action::kWait, 0.2, ""));
  bad.push_back(backwards);
  for (double duration : {nan, inf, -1.0, kMaxPlanDuration * 2}) {
    Plan plan = plankOnTop(0.0);
    plan.duration = duration;
    bad.push_back(plan);
  }
  Plan short_plan = backwards;
  short_plan.steps.pop_back();
  short_plan.duration = 0.3;  // before its last step
  bad.push_back(short_plan);
  for (double distance : {nan, 0.0, -0.01}) {
    Plan plan = plankOnTop(0.0);
    plan.fall_distance = distance;
    bad.push_back(plan);
  }
  for (double angle : {nan, 0.0, -0.1}) {
    Plan plan = plankOnTop(0.0);
    plan.fall_angle = angle;
    bad.push_back(plan);
  }
  for (const Plan& plan : bad) {
    PlanOutcome outcome;
    EXPECT_FALSE(checkPlan(plan).ok);
    EXPECT_FALSE(runPlan(plan, world.get(), &outcome).ok);
  }
  EXPECT_EQ(test::fingerprint(*world), before);
}

TEST(PlanCopyInMode, AFrozenTowerIsJudgedAnewByAnotherModel) {
  auto live = frozenTower("com");
  for (const std::string& mode : test::allModes()) {
    std::unique_ptr<BrickWorld> copy;
    ASSERT_TRUE(live->copyInMode(mode, &copy).ok) << mode;
    EXPECT_EQ(copy->options().stability.mode, mode);
    EXPECT_EQ(copy->time(), live->time());
    ASSERT_EQ(copy->brickIds(), live->brickIds());
    for (const BrickSnapshot& brick : copy->snapshot()) {
      // Statics holds every brick of the tower: a model freezes it at once.
      if (mode != "none") {
        EXPECT_NE(brick.state, BrickState::kDynamic) << mode << " " << brick.id;
      }
    }
  }
  std::unique_ptr<BrickWorld> copy;
  EXPECT_FALSE(live->copyInMode("no_such_mode", &copy).ok);
  EXPECT_EQ(copy, nullptr);
}

}  // namespace
}  // namespace brick_stack_sim
