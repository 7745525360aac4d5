// The node's pacing without a master: sim time follows wall time times
// real_time_factor, a world too heavy to keep up is not made to catch up in a
// burst, ~bricks follows sim time at publish_rate but no faster than twice
// that in wall time, and an idle node ticks at publish_rate.
#include <gtest/gtest.h>

#include "brick_stack_sim/ros/step_pacer.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

StepPacer::Options pacing(double real_time_factor) {
  StepPacer::Options options;
  options.time_step = 0.001;
  options.real_time_factor = real_time_factor;
  options.max_steps_per_tick = 2000;
  options.publish_rate = 30.0;
  options.step_timer_rate = 200.0;
  return options;
}

TEST(StepPacer, OwesTheStepsThatBringSimTimeToWallTimeTimesTheFactor) {
  StepPacer pacer(pacing(2.0));
  pacer.restart(100.0, 5.0);
  // 5 ms of wall time at factor 2 are 10 ms of sim time: 10 steps of 1 ms.
  EXPECT_EQ(pacer.stepsWanted(100.005, 5.0), 10.0);
  // Three of them done already: seven are owed.
  EXPECT_EQ(pacer.stepsWanted(100.005, 5.003), 7.0);
  // A world ahead of the clock is owed nothing, not a negative count.
  EXPECT_EQ(pacer.stepsWanted(100.005, 5.5), 0.0);
}

TEST(StepPacer, AStepDueExactlyNowIsNotLostToRounding) {
  StepPacer pacer(pacing(1.0));
  pacer.restart(0.0, 0.0);
  // 0.003 / 0.001 is 2.9999999999999996 in binary: still three steps.
  EXPECT_EQ(pacer.stepsWanted(0.003, 0.0), 3.0);
}

TEST(StepPacer, AsFastAsPossibleTakesTheWholeTickBound) {
  StepPacer pacer(pacing(0.0));
  pacer.restart(0.0, 0.0);
  EXPECT_EQ(pacer.stepsWanted(123.0, 4.0), 2000.0);
  EXPECT_FALSE(pacer.fellBehind(2000.0, 0)) << "with no clock to follow nothing is late";
}

TEST(StepPacer, ATickNeverTakesMoreThanItsBound) {
  StepPacer pacer(pacing(1.0));
  EXPECT_EQ(pacer.stepLimit(5000.0), 2000);
  EXPECT_EQ(pacer.stepLimit(17.0), 17);
}

TEST(StepPacer, FallsBehindOnlyPastATenthOfASecondOfWallTime) {
  StepPacer pacer(pacing(1.0));
  // 100 steps of 1 ms left at factor 1 are exactly 0.1 s: not yet behind.
  EXPECT_FALSE(pacer.fellBehind(150.0, 50));
  EXPECT_TRUE(pacer.fellBehind(151.0, 50));
  // At factor 4 the same 101 steps are 25 ms of wall time.
  StepPacer fast(pacing(4.0));
  EXPECT_FALSE(fast.fellBehind(151.0, 50));
}

TEST(StepPacer, PublishesAtPublishRateOfSimTime) {
  StepPacer pacer(pacing(1.0));
  pacer.schedulePublish(0.0);
  const double period = 1.0 / 30.0;
  EXPECT_TRUE(pacer.publishDue(0.0, 10.0, 0.0));
  pacer.published(0.0);
  EXPECT_FALSE(pacer.publishDue(0.5 * period, 10.0, 0.0));
  EXPECT_TRUE(pacer.publishDue(period, 10.0, 0.0));
  pacer.published(period);
  // A schedule that fell behind restarts one period from now rather than
  // sending every missed message at once.
  pacer.published(1.0);
  EXPECT_FALSE(pacer.publishDue(1.0 + 0.5 * period, 10.0, 0.0));
  EXPECT_TRUE(pacer.publishDue(1.0 + period, 10.0, 0.0));
}

TEST(StepPacer, PublishesNoFasterThanTwicePublishRateOfWallTime) {
  // Factor 1: at most 2 x 30 per wall second, one per 1/60 s.
  StepPacer pacer(pacing(1.0));
  pacer.schedulePublish(0.0);
  EXPECT_FALSE(pacer.publishDue(5.0, 10.0, 10.0 - 0.5 / 60.0));
  EXPECT_TRUE(pacer.publishDue(5.0, 10.0, 10.0 - 1.0 / 60.0));
  // Factor 10: ten times as many, one per 1/600 s.
  StepPacer fast(pacing(10.0));
  fast.schedulePublish(0.0);
  EXPECT_TRUE(fast.publishDue(5.0, 10.0, 10.0 - 1.0 / 600.0));
  EXPECT_FALSE(fast.publishDue(5.0, 10.0, 10.0 - 0.5 / 600.0));
}

TEST(StepPacer, AnIdleTimerTicksAtPublishRate) {
  StepPacer pacer(pacing(1.0));
  EXPECT_EQ(pacer.timerRate(false), 200.0);
  EXPECT_EQ(pacer.timerRate(true), 30.0);
  // Never faster idle than busy.
  StepPacer::Options slow = pacing(1.0);
  slow.step_timer_rate = 20.0;
  EXPECT_EQ(StepPacer(slow).timerRate(true), 20.0);
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
