// Leaning bricks, card house elements and counterweights in a running world:
// placed at rest (Bullet cannot hold a V of planks for one step, so they are
// judged from geometry before it steps them), then simulated. Thresholds are
// the hand-derived ones of support/leaning.h and test_rigid_block_statics.cpp.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "support/kapla.h"
#include "support/leaning.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaThickness;

/// A world in `mode` whose KAPLA and table both have friction `mu`, so
/// every pair has it.
std::unique_ptr<BrickWorld> worldWithFriction(const std::string& mode, double mu) {
  BrickTypeLibrary types;
  BrickType kapla = *test::packageTypes().find("kapla");
  kapla.friction = mu;
  EXPECT_TRUE(types.add(kapla).ok);
  EXPECT_TRUE(types.setDefaultType("kapla").ok);
  WorldOptions options = test::optionsFor(mode);
  options.table.friction = mu;
  std::unique_ptr<BrickWorld> world;
  const Status created = BrickWorld::create(options, types, &world);
  EXPECT_TRUE(created.ok) << created.message;
  return world;
}

BrickPlacement at(const std::string& id, const Eigen::Isometry3d& pose) {
  BrickPlacement p;
  p.id = id;
  p.pose = pose;
  return p;
}

BrickSnapshot brick(const BrickWorld& world, const std::string& id) {
  BrickSnapshot snapshot;
  EXPECT_TRUE(world.find(id, &snapshot)) << id;
  return snapshot;
}

/// How far a brick's centre is from where it was placed [m].
double displacement(const BrickWorld& world, const std::string& id) {
  const BrickSnapshot b = brick(world, id);
  return (b.pose.translation() - b.placed_pose.translation()).norm();
}

class LeaningInMode : public ::testing::TestWithParam<std::string> {};

TEST_P(LeaningInMode, VOfPlanksPlacedAtRestStandsBelowTheThresholdAndFallsAbove) {
  for (double mu : {0.3, 0.5}) {
    for (double factor : {0.9, 1.1}) {
      SCOPED_TRACE("mu " + std::to_string(mu) + ", " + std::to_string(factor) + " x threshold");
      auto world = worldWithFriction(GetParam(), mu);
      const auto [left, right] = test::vPlanks(factor * test::vThresholdAngle(mu));
      ASSERT_TRUE(world->addBrick(at("left", left)).ok);
      ASSERT_TRUE(world->addBrick(at("right", right)).ok);
      const bool stands = factor < 1.0;
      EXPECT_EQ(brick(*world, "left").state, stands ? BrickState::kLeaning : BrickState::kDynamic);
      EXPECT_EQ(brick(*world, "right").state, stands ? BrickState::kLeaning : BrickState::kDynamic);
      test::runFor(world.get(), 1.0);
      if (stands) {
        EXPECT_EQ(brick(*world, "left").state, BrickState::kLeaning);
        EXPECT_EQ(displacement(*world, "left"), 0.0);
        EXPECT_EQ(displacement(*world, "right"), 0.0);
      } else {
        // The apex, at L cos(theta) ~ 7 cm, comes down: the planks lie flat.
        EXPECT_LT(brick(*world, "left").pose.translation().z(), 0.02);
        EXPECT_LT(brick(*world, "right").pose.translation().z(), 0.02);
      }
    }
  }
}

TEST_P(LeaningInMode, OnePlankOfAVAloneIsNotHeld) {
  auto world = worldWithFriction(GetParam(), 0.5);
  ASSERT_TRUE(world->addBrick(at("left", test::vPlanks(0.5).first)).ok);
  EXPECT_EQ(brick(*world, "left").state, BrickState::kDynamic);
  test::runFor(world.get(), 1.0);
  EXPECT_LT(brick(*world, "left").pose.translation().z(), 0.02);
}

INSTANTIATE_TEST_SUITE_P(Modes, LeaningInMode, ::testing::Values("equilibrium"));

/// Flat KAPLAs placed at rest one per level from the table up, centred at
/// `x[i]` L; returns the world after `seconds`.
std::unique_ptr<BrickWorld> flatStack(const std::string& mode, const std::vector<double>& x,
                                      double seconds) {
  auto world = worldWithFriction(mode, 0.5);
  for (std::size_t level = 0; level < x.size(); ++level) {
    const Status placed = world->addBrick(test::placement(
        "p" + std::to_string(level),
        Eigen::Vector3d(x[level] * kKaplaLength, 0.0, (level + 0.5) * kKaplaThickness)));
    EXPECT_TRUE(placed.ok) << placed.message;
  }
  test::runFor(world.get(), seconds);
  return world;
}

TEST(Equilibrium, CounterweightedOverhangsFreezeWithZeroDrift) {
  // The stacks of RigidBlockStatics.CounterweightsHoldOverhangsThatFallWithoutThem.
  for (const std::vector<double>& x :
       {std::vector<double>{0.0, 0.7, 0.25}, std::vector<double>{0.0, 0.75, 0.35, 0.25}}) {
    auto world = flatStack("equilibrium", x, 2.0);
    for (std::size_t level = 0; level < x.size(); ++level) {
      const std::string id = "p" + std::to_string(level);
      EXPECT_EQ(brick(*world, id).state, BrickState::kStable) << id << " of " << x.size();
      EXPECT_EQ(displacement(*world, id), 0.0) << id << " of " << x.size();
    }
  }
}

TEST(Equilibrium, OverhangsWithoutTheirLastCounterweightFall) {
  for (const std::vector<double>& x :
       {std::vector<double>{0.0, 0.7}, std::vector<double>{0.0, 0.75, 0.35}}) {
    auto world = flatStack("equilibrium", x, 2.0);
    // The overhanging plank tips over its base's edge until its end
    // reaches the table: its centre drops and it turns.
    const BrickSnapshot plank = brick(*world, "p1");
    EXPECT_LT(plank.pose.translation().z(), 1.5 * kKaplaThickness - 1e-3) << x.size();
    const double tilt = std::acos(std::min(1.0, plank.pose.linear()(2, 2)));
    EXPECT_GT(tilt, 0.05) << x.size();
    EXPECT_EQ(brick(*world, "p0").state, BrickState::kStable);
  }
}

}  // namespace
}  // namespace brick_stack_sim
