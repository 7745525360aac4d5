// A brick's mode and the sets it implies: transfer() is the only way a
// brick changes mode, and after any sequence of transfers every container
// (Bullet's world and dynamics, the movers, the dormant colliders, the held
// bricks) agrees with every brick's mode.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "bullet/bullet_scene.h"
#include "bullet/dormant_colliders.h"
#include "support/kapla.h"
#include "world/brick_sets.h"

namespace brick_stack_sim {
namespace {

constexpr BrickMode kModes[] = {BrickMode::kDynamic, BrickMode::kFrozenStable,
                                BrickMode::kFrozenLeaning, BrickMode::kHeld};

class BrickSetsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = std::make_unique<BulletScene>(WorldOptions());
    dormant_ = std::make_unique<DormantColliders>(scene_.get());
    sets_ = std::make_unique<BrickSets>(scene_.get(), dormant_.get());
    const BrickType kapla = *test::packageTypes().find("kapla");
    for (BodyHandle h = 0; h < 3; ++h) {
      auto brick = std::make_unique<BrickRecord>();
      brick->id = "b" + std::to_string(h);
      brick->type = kapla;
      brick->handle = h;
      scene_->addBrick(h, kapla, test::placement(brick->id, {0.2 * h, 0, 0.0039}));
      sets_->enter(brick.get());
      bricks_.push_back(std::move(brick));
    }
  }

  std::vector<const BrickRecord*> records() const {
    std::vector<const BrickRecord*> result;
    for (const auto& brick : bricks_) result.push_back(brick.get());
    return result;
  }

  std::unique_ptr<BulletScene> scene_;
  std::unique_ptr<DormantColliders> dormant_;
  std::unique_ptr<BrickSets> sets_;
  std::vector<std::unique_ptr<BrickRecord>> bricks_;
};

TEST_F(BrickSetsTest, EveryTransferBetweenEveryPairOfModesKeepsTheSetsConsistent) {
  ASSERT_TRUE(sets_->checkInvariants(records()).ok);
  BrickRecord* brick = bricks_[1].get();
  for (BrickMode from : kModes) {
    for (BrickMode to : kModes) {
      sets_->transfer(brick, from);
      sets_->transfer(brick, to);
      EXPECT_EQ(brick->mode, to);
      const Status consistent = sets_->checkInvariants(records());
      EXPECT_TRUE(consistent.ok) << toString(from) << " -> " << toString(to) << ": "
                                 << consistent.message;
    }
  }
}

TEST_F(BrickSetsTest, EachModeHasTheBulletBodyItNeeds) {
  BrickRecord* brick = bricks_[0].get();
  sets_->transfer(brick, BrickMode::kFrozenStable);
  EXPECT_EQ(scene_->dynamics(0), BodyDynamics::kStatic);
  EXPECT_FALSE(scene_->inWorld(0));  // waits among the dormant colliders
  EXPECT_TRUE(dormant_->contains(0));
  sets_->transfer(brick, BrickMode::kHeld);
  EXPECT_EQ(scene_->dynamics(0), BodyDynamics::kKinematic);
  EXPECT_TRUE(scene_->inWorld(0));  // a held brick pushes what it touches
  EXPECT_FALSE(dormant_->contains(0));
  sets_->transfer(brick, BrickMode::kDynamic);
  EXPECT_EQ(scene_->dynamics(0), BodyDynamics::kDynamic);
  EXPECT_TRUE(scene_->isActive(0));
  // Back among the movers, in placement order.
  ASSERT_EQ(sets_->movers().size(), 3u);
  EXPECT_EQ(sets_->movers()[0], brick);
}

TEST_F(BrickSetsTest, MoversStayInPlacementOrder) {
  sets_->transfer(bricks_[0].get(), BrickMode::kFrozenStable);
  sets_->transfer(bricks_[2].get(), BrickMode::kHeld);
  ASSERT_EQ(sets_->movers().size(), 1u);
  sets_->transfer(bricks_[2].get(), BrickMode::kDynamic);
  sets_->transfer(bricks_[0].get(), BrickMode::kDynamic);
  ASSERT_EQ(sets_->movers().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(sets_->movers()[i]->handle, i);
}

TEST_F(BrickSetsTest, ABrickThatLeavesIsInNoSet) {
  sets_->transfer(bricks_[1].get(), BrickMode::kFrozenLeaning);
  sets_->leave(bricks_[1].get());
  scene_->removeBrick(1);
  bricks_.erase(bricks_.begin() + 1);
  EXPECT_TRUE(sets_->checkInvariants(records()).ok);
  EXPECT_EQ(dormant_->size(), 0u);
}

TEST_F(BrickSetsTest, TheCheckFindsABrickOutOfItsSet) {
  // A mode changed behind transfer()'s back is what the check is for.
  bricks_[2]->mode = BrickMode::kFrozenStable;
  const Status broken = sets_->checkInvariants(records());
  EXPECT_FALSE(broken.ok);
  EXPECT_NE(broken.message.find("b2"), std::string::npos) << broken.message;
}

}  // namespace
}  // namespace brick_stack_sim
