#include <cmath>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::fingerprint;
using test::kKaplaThickness;
using test::makeWorld;
using test::placement;
using test::runFor;

TEST(BrickWorld, DroppedBrickComesToRestFlatOnTheTable) {
  auto world = makeWorld();
  ASSERT_TRUE(world->addBrick(placement("b0", {0.01, -0.02, 0.05})).ok);
  runFor(world.get(), 2.0);
  BrickSnapshot brick;
  ASSERT_TRUE(world->find("b0", &brick));
  // Resting on its broad face: centre at half the thickness, 3.9 mm.
  EXPECT_NEAR(brick.pose.translation().z(), kKaplaThickness / 2, 0.2e-3);
  EXPECT_NEAR(brick.pose.translation().x(), 0.01, 0.2e-3);
  EXPECT_NEAR(brick.pose.translation().y(), -0.02, 0.2e-3);
  // Flat: its thin axis points up.
  EXPECT_GT(brick.pose.linear().col(2).z(), std::cos(0.01));
  EXPECT_LT(brick.linear_velocity.norm(), 1e-3);
  EXPECT_FALSE(brick.fell_off);
}

TEST(BrickWorld, SameCallsGiveBitIdenticalPoses) {
  auto build_and_run = [] {
    auto world = makeWorld();
    for (int layer = 0; layer < 6; ++layer) {
      const double yaw = layer % 2 ? M_PI / 2 : 0.0;
      const double z = kKaplaThickness * (layer + 0.5) + 0.002;  // dropped a little
      for (double lane : {-0.0468, 0.0468}) {
        const Eigen::Vector3d at = layer % 2 ? Eigen::Vector3d(lane, 0.001 * layer, z)
                                             : Eigen::Vector3d(0.001 * layer, lane, z);
        EXPECT_TRUE(world->addBrick(placement("", at, yaw + 0.01 * layer)).ok);
      }
    }
    runFor(world.get(), 1.5);
    return fingerprint(*world);
  };
  const std::string first = build_and_run();
  const std::string second = build_and_run();
  ASSERT_EQ(first.size(), second.size());
  EXPECT_TRUE(first == second) << "two identical runs diverged";
}

TEST(BrickWorld, AssignsIdsAndReportsEvents) {
  auto world = makeWorld();
  std::string id;
  ASSERT_TRUE(world->addBrick(placement("", {0, 0, 0.0039}), &id).ok);
  EXPECT_EQ(id, "brick_0");
  ASSERT_TRUE(world->addBrick(placement("brick_1", {0, 0.05, 0.0039})).ok);
  ASSERT_TRUE(world->addBrick(placement("", {0, 0.1, 0.0039}), &id).ok);
  EXPECT_EQ(id, "brick_2");  // brick_1 was taken by name
  auto events = world->takeEvents();
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].kind, SimEventKind::kSpawned);
  EXPECT_EQ(events[1].brick_id, "brick_1");
  EXPECT_TRUE(world->takeEvents().empty());
}

TEST(BrickWorld, RemovingTheLowerBrickWakesTheUpperOneWhichFalls) {
  auto world = makeWorld();
  ASSERT_TRUE(world->addBrick(placement("low", {0, 0, 0.0039})).ok);
  ASSERT_TRUE(world->addBrick(placement("high", {0, 0, 0.0117})).ok);
  runFor(world.get(), 3.0);  // long enough for Bullet to put both to sleep
  BrickSnapshot high;
  ASSERT_TRUE(world->find("high", &high));
  ASSERT_TRUE(high.asleep);
  world->takeEvents();
  ASSERT_TRUE(world->removeBrick("low").ok);
  auto events = world->takeEvents();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, SimEventKind::kRemoved);
  EXPECT_EQ(events[0].affected, std::vector<std::string>{"high"});
  runFor(world.get(), 0.5);
  ASSERT_TRUE(world->find("high", &high));
  EXPECT_NEAR(high.pose.translation().z(), kKaplaThickness / 2, 0.2e-3);
  EXPECT_EQ(world->brickCount(), 1u);
  EXPECT_FALSE(world->find("low", nullptr));
}

TEST(BrickWorld, BrickPushedOffTheTableIsReportedAndLandsOnTheFloor) {
  WorldOptions options = test::plainBulletOptions();
  options.table.size = Eigen::Vector2d(0.3, 0.3);
  auto world = makeWorld(options);
  BrickPlacement p = placement("slider", {0.1, 0, 0.0039});
  p.linear_velocity = Eigen::Vector3d(2.0, 0, 0);
  ASSERT_TRUE(world->addBrick(p).ok);
  runFor(world.get(), 1.5);
  bool fell = false;
  for (const SimEvent& e : world->takeEvents()) fell |= e.kind == SimEventKind::kFellOff;
  EXPECT_TRUE(fell);
  BrickSnapshot brick;
  ASSERT_TRUE(world->find("slider", &brick));  // nothing is lost
  EXPECT_TRUE(brick.fell_off);
  // On the floor, 0.75 m below the table top; it may rest on any face.
  EXPECT_LT(brick.pose.translation().z(), -0.75 + 0.06);
  EXPECT_GT(brick.pose.translation().z(), -0.75);
}

TEST(BrickWorld, ImpulseMovesTheBrickByMomentum) {
  WorldOptions options = test::plainBulletOptions();
  options.gravity = 0.0;  // free flight: momentum is all there is
  auto world = makeWorld(options);
  ASSERT_TRUE(world->addBrick(placement("b", {0, 0, 0.1})).ok);
  ASSERT_TRUE(world->applyImpulse("b", {0.0119 * 0.1, 0, 0}, {0, 0, 0.1}).ok);
  runFor(world.get(), 0.5);
  BrickSnapshot b;
  ASSERT_TRUE(world->find("b", &b));
  EXPECT_NEAR(b.linear_velocity.x(), 0.1, 1e-9);  // J / m
  EXPECT_NEAR(b.pose.translation().x(), 0.05, 1e-6);
  EXPECT_NEAR(b.angular_velocity.norm(), 0.0, 1e-9);  // applied at the centre
}

TEST(BrickWorld, CostCountsAwakeBricks) {
  auto world = makeWorld();
  ASSERT_TRUE(world->addBrick(placement("a", {0, 0, 0.0039})).ok);
  ASSERT_TRUE(world->addBrick(placement("b", {0, 0.05, 0.0039})).ok);
  world->step();
  world->step();
  EXPECT_EQ(world->cost().steps, 2u);
  EXPECT_EQ(world->cost().bullet_steps, 2u);
  EXPECT_EQ(world->cost().awake_brick_steps, 4u);
  EXPECT_EQ(world->cost().nonfinite, 0u);
}

// Wall times differ between runs: only what holds on any machine is checked.
TEST(BrickWorld, BulletStagesArePartsOfBulletsTime) {
  auto world = makeWorld();
  // Three bricks dropped onto the table and onto each other: they touch.
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d at(0.001 * i, 0.0, kKaplaThickness * (i + 0.5) + 0.002 * (i + 1));
    ASSERT_TRUE(world->addBrick(placement("", at, 0.3 * i)).ok);
  }
  runFor(world.get(), 0.3);
  const CostCounters& cost = world->cost();
  const BulletStageSeconds& stages = cost.bullet_stages;
  for (double seconds :
       {stages.broadphase, stages.narrowphase, stages.islands, stages.solver, stages.integration}) {
    EXPECT_TRUE(std::isfinite(seconds));
    EXPECT_GE(seconds, 0.0);
  }
  EXPECT_LE(stages.total(), cost.bullet_seconds + 1e-9);
  EXPECT_GT(stages.narrowphase, 0.0);
  EXPECT_GT(stages.solver, 0.0);
  // A copy goes on from the counters it was copied with.
  const std::unique_ptr<BrickWorld> copy = world->copy();
  EXPECT_EQ(copy->cost().bullet_stages.solver, stages.solver);
}

}  // namespace
}  // namespace brick_stack_sim
