// The simulation object the batch runner and the node's ~reset share: a
// world, the scene it plays, and a clock that never goes backwards.
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/simulation/simulation.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::placement;

std::unique_ptr<Simulation> makeSimulation(
    const WorldOptions& options = test::plainBulletOptions()) {
  std::unique_ptr<Simulation> simulation;
  const Status created = Simulation::create(options, test::packageTypes(), &simulation);
  EXPECT_TRUE(created.ok) << created.message;
  return simulation;
}

Scene twoBricksAtTimes() {
  Scene scene;
  scene.name = "two";
  ScheduledBrick first{placement("a", {0, 0, 0.0039}), 0.0};
  ScheduledBrick second{placement("b", {0, 0.05, 0.0039}), 0.5};
  scene.bricks = {first, second};
  return scene;
}

TEST(Simulation, ResetEmptiesTheTableButTimeGoesOn) {
  std::unique_ptr<Simulation> simulation;
  ASSERT_TRUE(Simulation::create(test::plainBulletOptions(), test::packageTypes(), &simulation).ok);
  ASSERT_TRUE(simulation->world().addBrick(placement("a", {0, 0, 0.0039})).ok);
  for (int i = 0; i < 100; ++i) simulation->step();
  const double before = simulation->time();
  ASSERT_TRUE(simulation->reset(Scene()).ok);
  EXPECT_EQ(simulation->world().brickCount(), 0u);
  EXPECT_DOUBLE_EQ(simulation->time(), before);
  const std::vector<SimEvent> events = simulation->takeEvents();
  ASSERT_EQ(events.size(), 2u);  // spawned, then removed by the reset
  EXPECT_EQ(events[1].kind, SimEventKind::kRemoved);
  EXPECT_EQ(events[1].reason, "scene reset");
  EXPECT_DOUBLE_EQ(events[1].time, before);
  simulation->step();
  EXPECT_GT(simulation->time(), before);
  std::string id;
  ASSERT_TRUE(simulation->world().addBrick(placement("", {0, 0, 0.0039}), &id).ok);
  EXPECT_EQ(id, "brick_0");
}

TEST(Simulation, AScenePlaysItsBricksAtTheirTimesFromTheReset) {
  auto simulation = makeSimulation();
  for (int i = 0; i < 250; ++i) simulation->step();
  const double start = simulation->time();
  ASSERT_TRUE(simulation->reset(twoBricksAtTimes()).ok);
  EXPECT_EQ(simulation->world().brickCount(), 1u);  // due at once
  EXPECT_EQ(simulation->player().pending(), 1u);
  while (simulation->world().brickCount() < 2) simulation->step();
  BrickSnapshot b;
  ASSERT_TRUE(simulation->world().find("b", &b));
  EXPECT_NEAR(b.placed_at, start + 0.5, 1e-9);  // placed_at in the clock that goes on
  EXPECT_TRUE(simulation->takeRefused().empty());
}

TEST(Simulation, ASceneWithItsOwnTableGetsAWorldOfItsOwnAndTheNextResetGoesBack) {
  auto simulation = makeSimulation();
  Scene narrow;
  narrow.table = TableOptions();
  narrow.table->size = Eigen::Vector2d(0.3, 0.2);
  ASSERT_TRUE(simulation->reset(narrow).ok);
  EXPECT_EQ(simulation->world().options().table.size, Eigen::Vector2d(0.3, 0.2));
  ASSERT_TRUE(simulation->reset(Scene()).ok);
  EXPECT_EQ(simulation->world().options().table.size, WorldOptions().table.size);
}

TEST(Simulation, AResetThatCannotBeMadeChangesNothing) {
  auto simulation = makeSimulation();
  ASSERT_TRUE(simulation->world().addBrick(placement("a", {0, 0, 0.0039})).ok);
  for (int i = 0; i < 10; ++i) simulation->step();
  simulation->takeEvents();
  const std::string before = test::fingerprint(simulation->world());
  Scene bad;
  bad.table = TableOptions();
  bad.table->thickness = -1.0;
  const Status refused = simulation->reset(bad);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(refused.message.find("thickness"), std::string::npos) << refused.message;
  EXPECT_TRUE(test::fingerprint(simulation->world()) == before);
  EXPECT_TRUE(simulation->takeEvents().empty());
}

TEST(Simulation, ASceneWithABrickOutsideTheWorldBoxIsRefusedWhole) {
  auto simulation = makeSimulation();
  ASSERT_TRUE(simulation->world().addBrick(placement("a", {0, 0, 0.0039})).ok);
  simulation->takeEvents();
  const std::string before = test::fingerprint(simulation->world());
  Scene scene = twoBricksAtTimes();
  scene.bricks[1].placement.pose.translation() = Eigen::Vector3d(1e300, 0, 0.0039);
  const Status refused = simulation->reset(scene);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(refused.message.find("brick 'b'"), std::string::npos) << refused.message;
  EXPECT_NE(refused.message.find("outside the world box"), std::string::npos) << refused.message;
  EXPECT_TRUE(test::fingerprint(simulation->world()) == before);
  EXPECT_TRUE(simulation->takeEvents().empty());
}

TEST(Simulation, ABrickThatLeavesTheWorldBoxIsRemovedAndReportedLost) {
  // Thrown straight up at 20 m/s it would climb 20 m: past a 2 m box after
  // about 0.1 s, it is removed with a lost event instead of flying on.
  WorldOptions options = test::plainBulletOptions();
  options.bounds.height = 2.0;
  auto simulation = makeSimulation(options);
  BrickPlacement thrown = placement("up", {0, 0, 0.5});
  thrown.linear_velocity = Eigen::Vector3d(0, 0, 20.0);
  ASSERT_TRUE(simulation->world().addBrick(thrown).ok);
  ASSERT_TRUE(simulation->world().addBrick(placement("stays", {0.3, 0, 0.0039})).ok);
  simulation->takeEvents();
  std::vector<SimEvent> lost;
  for (int i = 0; i < 300; ++i) {
    simulation->step();
    for (const SimEvent& event : simulation->takeEvents())
      if (event.kind == SimEventKind::kLost) lost.push_back(event);
  }
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_EQ(lost[0].brick_id, "up");
  EXPECT_NE(lost[0].reason.find("left the world box"), std::string::npos) << lost[0].reason;
  // z = 0.5 + 20 t - g t^2 / 2 passes 2 m at t = 0.0784 s.
  EXPECT_NEAR(lost[0].time, 0.0784, 0.002);
  EXPECT_EQ(simulation->world().brickCount(), 1u);
  BrickSnapshot gone;
  EXPECT_FALSE(simulation->world().find("up", &gone));
  EXPECT_EQ(simulation->world().cost().lost, 1u);
}

TEST(Simulation, RefusedScenePlacementsAreKeptForTheCaller) {
  auto simulation = makeSimulation();
  Scene scene = twoBricksAtTimes();
  scene.bricks[1].placement.pose.translation() = Eigen::Vector3d(0, 0, 0.0039);  // inside a
  ASSERT_TRUE(simulation->reset(scene).ok);
  for (int i = 0; i < 600; ++i) simulation->step();
  const std::vector<RefusedPlacement> refused = simulation->takeRefused();
  ASSERT_EQ(refused.size(), 1u);
  EXPECT_EQ(refused[0].id, "b");
  EXPECT_NE(refused[0].reason.find("overlaps brick 'a'"), std::string::npos) << refused[0].reason;
  EXPECT_TRUE(simulation->takeRefused().empty());
}

}  // namespace
}  // namespace brick_stack_sim
