// A pile of planks dropped on the table freezes whole in com, with Bullet's
// impulses carried over whole (full_warm_start, the setting that lets com
// freeze pile1000): planks leaning on planks that are themselves at rest
// join the stack as groups, judged by statics with every plank that props
// them, and a settled pile is then only the clock. (Towers of flat planks
// rock in Bullet with that setting, so a pile dropped as 5 x 4 towers of 15
// does not: docs/benchmarks.md, "Piles left to settle".)

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/simulation/simulation.h"
#include "support/kapla.h"
#include "support/scenes.h"

namespace brick_stack_sim {
namespace {

bool frozen(BrickState state) {
  return state == BrickState::kStable || state == BrickState::kLeaning;
}

TEST(FullWarmStartPile, TwoHundredDroppedPlanksFreezeWithinSecondsOfLanding) {
  // pile200: 200 planks over 7 x 5 cells, 6 layers; they land within 1 s.
  WorldOptions options;
  options.stability.mode = "com";
  options.full_warm_start = true;
  std::unique_ptr<Simulation> simulation;
  ASSERT_TRUE(Simulation::create(options, test::packageTypes(), &simulation).ok);
  ASSERT_TRUE(simulation->reset(test::droppedPileScene(200, 7, 5, 1)).ok);
  while (simulation->world().time() < 4.0) simulation->step();

  std::size_t frozen_bricks = 0, bricks = 0;
  for (const BrickSnapshot& brick : simulation->world().snapshot()) {
    ++bricks;
    frozen_bricks += frozen(brick.state);
  }
  EXPECT_EQ(bricks, 200u);  // nothing lost
  // 98 % frozen within 3 s of landing (docs/benchmarks.md, "Piles left to settle").
  EXPECT_GE(frozen_bricks, 196u);

  // Frozen, they stay where they are: a second more moves none of them.
  const std::vector<BrickSnapshot> before = simulation->world().snapshot();
  while (simulation->world().time() < 5.0) simulation->step();
  const std::vector<BrickSnapshot> after = simulation->world().snapshot();
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (!frozen(before[i].state) || !frozen(after[i].state)) continue;
    EXPECT_TRUE(after[i].pose.matrix() == before[i].pose.matrix()) << after[i].id;
  }
}

}  // namespace
}  // namespace brick_stack_sim
