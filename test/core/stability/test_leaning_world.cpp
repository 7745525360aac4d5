// Leaning bricks, card house elements and counterweights in a running world:
// placed at rest (Bullet cannot hold a V of planks for one step, so they are
// judged from geometry before it steps them), then simulated. Thresholds are
// the hand-derived ones of support/leaning.h and test_rigid_block_statics.cpp.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/generators.h"
#include "support/kapla.h"
#include "support/leaning.h"
#include "support/modes.h"
#include "support/world_probe.h"

namespace brick_stack_sim {
namespace {

using test::at;
using test::displacement;
using test::kKaplaLength;
using test::kKaplaThickness;
using test::worldWithFriction;

/// Statics beyond the thesis's COM rule (leaning, pushing, counterweights),
/// in each mode that judges it.
class StaticsInMode : public ::testing::TestWithParam<std::string> {};

TEST_P(StaticsInMode, VOfPlanksPlacedAtRestStandsBelowTheThresholdAndFallsAbove) {
  for (double mu : {0.3, 0.5}) {
    for (double factor : {0.9, 1.1}) {
      SCOPED_TRACE("mu " + std::to_string(mu) + ", " + std::to_string(factor) + " x threshold");
      auto world = worldWithFriction(GetParam(), mu);
      const auto [left, right] = test::vPlanks(factor * test::vThresholdAngle(mu));
      ASSERT_TRUE(world->addBrick(at("left", left)).ok);
      ASSERT_TRUE(world->addBrick(at("right", right)).ok);
      const bool stands = factor < 1.0;
      EXPECT_EQ(test::snapshotOf(*world, "left").state,
                stands ? BrickState::kLeaning : BrickState::kDynamic);
      EXPECT_EQ(test::snapshotOf(*world, "right").state,
                stands ? BrickState::kLeaning : BrickState::kDynamic);
      test::runFor(world.get(), 1.0);
      if (stands) {
        EXPECT_EQ(test::snapshotOf(*world, "left").state, BrickState::kLeaning);
        EXPECT_EQ(displacement(*world, "left"), 0.0);
        EXPECT_EQ(displacement(*world, "right"), 0.0);
      } else {
        // The apex, at L cos(theta) ~ 7 cm, comes down: the planks lie flat.
        EXPECT_LT(test::snapshotOf(*world, "left").pose.translation().z(), 0.02);
        EXPECT_LT(test::snapshotOf(*world, "right").pose.translation().z(), 0.02);
      }
    }
  }
}

TEST_P(StaticsInMode, AVThatComesToRestInBulletFreezesAsOneGroup) {
  // Let go just above rest, the planks are movers: each leans on the other,
  // which is not frozen, so neither joins the stack alone. At rest together
  // on the table, statics holds the V below tan(theta) = 2 mu + T/L
  // (vThresholdAngle): it joins as a group, where Bullet left it. (Plain
  // Bullet at 1 ms lets a V slide apart from 0.3 of that angle on: the
  // steep V is one it holds.)
  const double mu = 0.5;
  for (double factor : {0.15, 1.3}) {
    SCOPED_TRACE(std::to_string(factor) + " x threshold");
    auto world = worldWithFriction(GetParam(), mu);
    auto [left, right] = test::vPlanks(factor * test::vThresholdAngle(mu));
    BrickPlacement l = at("left", left), r = at("right", right);
    l.linear_velocity = r.linear_velocity = Eigen::Vector3d(0.0, 0.0, -1e-4);
    ASSERT_TRUE(world->addBrick(l).ok);
    ASSERT_TRUE(world->addBrick(r).ok);
    test::runFor(world.get(), 1.0);
    const BrickSnapshot left_end = test::snapshotOf(*world, "left");
    if (factor < 1.0) {
      EXPECT_EQ(left_end.state, BrickState::kLeaning);
      EXPECT_EQ(test::snapshotOf(*world, "right").state, BrickState::kLeaning);
      // Frozen where it rested: a fraction of a millimetre from where it was let go.
      EXPECT_LT(displacement(*world, "left"), 5e-4);
      const Eigen::Isometry3d frozen_at = left_end.pose;
      test::runFor(world.get(), 0.5);
      EXPECT_TRUE(test::snapshotOf(*world, "left").pose.isApprox(frozen_at, 0.0));
    } else {
      // Beyond the threshold the apex comes down: the planks lie flat.
      EXPECT_LT(left_end.pose.translation().z(), 0.02);
    }
  }
}

TEST_P(StaticsInMode, AVComingToRestOnACantileverThatHoldsItFreezesOnIt) {
  // A base plank at x = 0 and on it a cantilever C at x = 36 mm, its COM
  // L/2 - 36 = 22.5 mm inside the base's edge at L/2. A V (the steep one
  // Bullet holds, its feet within 22 mm of its apex, all on C's top) let
  // go just above rest with its apex 8.5 mm beyond that edge: about the
  // edge the V's weight 2 m g tips C with 2 x 8.5 = 17 mm m g against C's
  // own 22.5 mm m g (the feet's sideways forces cancel), so everything
  // stands. Counted twice (as the load the resting V puts on C, and
  // through the V's contacts once it joins), the V would tip C with
  // 34 mm m g, and it was refused for ever where Bullet held it.
  const double mu = 0.5;
  auto world = worldWithFriction(GetParam(), mu);
  const double offset = 0.036, edge = 0.5 * kKaplaLength, apex_x = edge + 0.0085;
  ASSERT_TRUE(
      world->addBrick(test::placement("base", Eigen::Vector3d(0.0, 0.0, 0.5 * kKaplaThickness)))
          .ok);
  ASSERT_TRUE(
      world->addBrick(test::placement("c", Eigen::Vector3d(offset, 0.0, 1.5 * kKaplaThickness)))
          .ok);
  test::runFor(world.get(), 0.3);
  ASSERT_EQ(test::snapshotOf(*world, "c").state, BrickState::kStable);
  auto [left, right] = test::vPlanks(0.15 * test::vThresholdAngle(mu), apex_x);
  left.translation().z() += 2.0 * kKaplaThickness;
  right.translation().z() += 2.0 * kKaplaThickness;
  BrickPlacement l = at("left", left), r = at("right", right);
  l.linear_velocity = r.linear_velocity = Eigen::Vector3d(0.0, 0.0, -1e-4);
  ASSERT_TRUE(world->addBrick(l).ok);
  ASSERT_TRUE(world->addBrick(r).ok);
  test::runFor(world.get(), 2.0);
  EXPECT_EQ(test::snapshotOf(*world, "left").state, BrickState::kLeaning);
  EXPECT_EQ(test::snapshotOf(*world, "right").state, BrickState::kLeaning);
  EXPECT_LT(displacement(*world, "left"), 5e-4);
  EXPECT_EQ(test::snapshotOf(*world, "c").state, BrickState::kStable);
  EXPECT_EQ(displacement(*world, "c"), 0.0);
}

/// Forces a frozen brick's contacts carry must hold it in equilibrium with
/// its weight, within friction and without pulling, to the LP's tolerance.
void expectBalanced(const test::ForceBalance& balance) {
  constexpr double kLpTolerance = 1e-6;  // of a brick's weight; Clp's is 1e-7
  EXPECT_LT(balance.worst_force, kLpTolerance);
  EXPECT_LT(balance.worst_torque, kLpTolerance);
  EXPECT_LT(balance.worst_friction, kLpTolerance);
  EXPECT_LT(balance.worst_pull, kLpTolerance);
}

TEST_P(StaticsInMode, LeaningPlanksReportContactForcesThatHoldThem) {
  // A V at half its threshold: each plank's forces (feet on the table, the
  // other plank at the apex) balance its weight, force and torque, inside
  // the friction cones; at the apex the two planks push each other with
  // opposite forces (one contact, named from both sides).
  auto world = worldWithFriction(GetParam(), 0.5);
  const auto [left, right] = test::vPlanks(0.5 * test::vThresholdAngle(0.5));
  ASSERT_TRUE(world->addBrick(at("left", left)).ok);
  ASSERT_TRUE(world->addBrick(at("right", right)).ok);
  test::runFor(world.get(), 0.2);
  ASSERT_EQ(test::snapshotOf(*world, "left").state, BrickState::kLeaning);
  const test::ForceBalance balance = test::contactForceBalance(*world, {"left", "right"});
  EXPECT_EQ(balance.bricks_with_forces, 2);
  expectBalanced(balance);

  SupportGeometry on_left, on_right;
  ASSERT_TRUE(world->supportGeometry("left", &on_left));
  ASSERT_TRUE(world->supportGeometry("right", &on_right));
  Eigen::Vector3d apex_on_left = Eigen::Vector3d::Zero(), apex_on_right = Eigen::Vector3d::Zero();
  double table_lift = 0.0;
  for (const SupportGeometry::ContactForce& f : on_left.contact_forces) {
    if (f.other == "right") apex_on_left += f.force;
    if (f.other == "table") table_lift += f.force.z();
  }
  for (const SupportGeometry::ContactForce& f : on_right.contact_forces) {
    if (f.other == "left") apex_on_right += f.force;
    if (f.other == "table") table_lift += f.force.z();
  }
  const double weight = test::snapshotOf(*world, "left").mass * 9.81;
  // The planks lean on each other: the apex force is mostly horizontal,
  // towards each plank.
  EXPECT_GT(apex_on_left.norm(), 0.1 * weight);
  EXPECT_LT((apex_on_left + apex_on_right).norm(), 1e-6 * weight);
  // The table carries both planks.
  EXPECT_NEAR(table_lift, 2.0 * weight, 1e-6 * weight);
}

TEST_P(StaticsInMode, OnePlankOfAVAloneIsNotHeld) {
  auto world = worldWithFriction(GetParam(), 0.5);
  ASSERT_TRUE(world->addBrick(at("left", test::vPlanks(0.5).first)).ok);
  EXPECT_EQ(test::snapshotOf(*world, "left").state, BrickState::kDynamic);
  test::runFor(world.get(), 1.0);
  EXPECT_LT(test::snapshotOf(*world, "left").pose.translation().z(), 0.02);
}

/// A card house of two levels (thesis figure 10), built V by V: two V's
/// whose feet touch, a flat plank across their apexes, a V on that plank.
/// Each V at 20 degrees stands with margin (its threshold is 46.9 at mu
/// 0.5). A plank's highest edge is its outer top edge, T sin above the apex
/// (at L cos): those four edges carry the floor plank flat.
std::vector<BrickPlacement> twoLevelCardHouse() {
  const double theta = 20.0 * M_PI / 180.0;
  // Half the width of a V at its feet: L sin + T cos from apex to outer foot.
  const double half_base = kKaplaLength * std::sin(theta) + kKaplaThickness * std::cos(theta);
  const double top = kKaplaLength * std::cos(theta) + kKaplaThickness * std::sin(theta);
  std::vector<BrickPlacement> bricks;
  auto add_v = [&](const std::string& name, double apex_x, double base_z) {
    auto [left, right] = test::vPlanks(theta, apex_x);
    left.translation().z() += base_z;
    right.translation().z() += base_z;
    bricks.push_back(at(name + "_l", left));
    bricks.push_back(at(name + "_r", right));
  };
  add_v("v0", -half_base, 0.0);
  add_v("v1", half_base, 0.0);
  Eigen::Isometry3d floor = Eigen::Isometry3d::Identity();
  floor.translation() = Eigen::Vector3d(0.0, 0.0, top + 0.5 * kKaplaThickness);
  bricks.push_back(at("level", floor));
  add_v("v2", 0.0, top + kKaplaThickness);
  return bricks;
}

TEST_P(StaticsInMode, TwoLevelCardHouseBuiltVByVStandsStill) {
  auto world = worldWithFriction(GetParam(), 0.5);
  for (const BrickPlacement& placement : twoLevelCardHouse()) {
    const Status placed = world->addBrick(placement);
    ASSERT_TRUE(placed.ok) << placement.id << ": " << placed.message;
    // Bullet steps between the V's: each is judged as it is completed.
    if (placement.id.back() == 'r' || placement.id == "level") world->step();
  }
  test::runFor(world.get(), 2.0);
  for (const BrickPlacement& placement : twoLevelCardHouse()) {
    const BrickSnapshot b = test::snapshotOf(*world, placement.id);
    EXPECT_NE(b.state, BrickState::kDynamic) << placement.id;
    EXPECT_EQ(displacement(*world, placement.id), 0.0) << placement.id;
  }
}

/// A KAPLA standing on its end on the table, its thickness along x, its
/// left face at x = 0.
Eigen::Isometry3d standingOnEnd() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = test::leaningRotation(0.0);
  pose.translation() = Eigen::Vector3d(0.5 * kKaplaThickness, 0.0, 0.5 * kKaplaLength);
  return pose;
}

TEST_P(StaticsInMode, PlankLeaningOnABrickStandingOnItsEndTopplesIt) {
  // A plank at theta = 30 degrees from vertical, its upper inner edge on the
  // standing brick's face at h = L cos = 101 mm. Moments about its foot
  // (ladderThresholdAngle): H (cos + mu sin) L = m g (L sin - T cos) / 2
  // with the face's friction F <= mu H, so the push is at least
  // H = m g (0.5 - 0.0667 * 0.866) / (2 (0.866 + 0.25)) = 0.198 m g at mu
  // 0.5 (the plank stands: 30 < 55.3 degrees). The standing brick tips
  // about its far edge once H h > m g T/2 + F T: 20.1 > 3.9 + 0.77 (m g mm).
  // It topples, and the plank with it.
  auto world = worldWithFriction(GetParam(), 0.5);
  ASSERT_TRUE(world->addBrick(at("standing", standingOnEnd())).ok);
  test::runFor(world.get(), 0.5);
  ASSERT_EQ(test::snapshotOf(*world, "standing").state, BrickState::kStable);
  ASSERT_EQ(displacement(*world, "standing"), 0.0);
  const double theta = 30.0 * M_PI / 180.0;
  ASSERT_GT(test::ladderThresholdAngle(0.5, 0.5), theta);
  ASSERT_TRUE(world->addBrick(at("plank", test::plankLeaningTowardsX(theta, 0.0))).ok);
  EXPECT_EQ(test::snapshotOf(*world, "standing").state, BrickState::kDynamic);
  test::runFor(world.get(), 2.0);
  // Standing, its centre is L/2 = 58.5 mm up; lying, at most W/2.
  EXPECT_LT(test::snapshotOf(*world, "standing").pose.translation().z(), 0.3 * kKaplaLength);
  EXPECT_GT(test::turn(*world, "standing"), 0.5);
}

/// A cantilever: p0 and p1 flat on the table at x = 0, p2 on them at
/// x = `offset` (its COM L/2 - offset inside p1's edge at x = L/2; its free
/// end at offset + L/2, its top at 3 T), and a plank at 20 degrees from
/// horizontal, rising towards -x, its lower face on p2's free top edge E and
/// its foot on the table.
std::vector<BrickPlacement> loadedCantilever(double offset) {
  std::vector<BrickPlacement> bricks;
  for (int level = 0; level < 3; ++level)
    bricks.push_back(test::placement(
        "p" + std::to_string(level),
        Eigen::Vector3d(level == 2 ? offset : 0.0, 0.0, (level + 0.5) * kKaplaThickness)));
  const double slope = 20.0 * M_PI / 180.0;
  const Eigen::Vector3d along(std::cos(slope), 0.0, -std::sin(slope));  // down towards the foot
  const Eigen::Vector3d up(std::sin(slope), 0.0, std::cos(slope));      // its lower face's normal
  const Eigen::Vector3d edge(offset + 0.5 * kKaplaLength, 0.0, 3.0 * kKaplaThickness);
  const Eigen::Vector3d foot = edge + (3.0 * kKaplaThickness / std::sin(slope)) * along;
  Eigen::Isometry3d plank = Eigen::Isometry3d::Identity();
  plank.linear() = Eigen::AngleAxisd(slope, Eigen::Vector3d::UnitY()).toRotationMatrix();
  plank.translation() = foot - 0.5 * kKaplaLength * along + 0.5 * kKaplaThickness * up;
  bricks.push_back(at("plank", plank));
  return bricks;
}

TEST_P(StaticsInMode, PlankRestingOnACantileversFreeEndTipsItUnlessItSitsDeep) {
  // The plank's foot is d = 3 T / sin 20 = 68.4 mm from E along it. Its COM
  // is (L/2) cos 20 - (T/2) sin 20 = 53.6 mm from the foot horizontally,
  // inside E's 64.3: it leans on E. The face's friction passes through the
  // foot, so moments about the foot give the normal force at E exactly:
  // N = m g 53.6 / 68.4 = 0.78 m g, at 20 degrees from vertical. On p2 it
  // presses down between N (cos 20 -/+ mu sin 20) = 0.60 and 0.87 m g (mu
  // 0.5) at `offset` beyond p1's edge, and sideways (towards p1) with at
  // most N (sin 20 + mu cos 20) = 0.63 m g at T above that edge.
  //  - offset 0.4 L: about the edge, at least 0.60 * 0.4 L - 0.63 * 0.067 L
  //    = 0.20 L (m g) tips against p2's own 0.1 L: it tips.
  //  - offset 0.1 L: at most 0.87 * 0.1 L = 0.087 L tips against 0.4 L: it
  //    stands, and so does the plank.
  for (const double offset : {0.4 * kKaplaLength, 0.1 * kKaplaLength}) {
    const bool tips = offset > 0.2 * kKaplaLength;
    SCOPED_TRACE(tips ? "cantilever at 0.4 L" : "cantilever at 0.1 L");
    auto world = worldWithFriction(GetParam(), 0.5);
    const std::vector<BrickPlacement> bricks = loadedCantilever(offset);
    for (std::size_t i = 0; i + 1 < bricks.size(); ++i)
      ASSERT_TRUE(world->addBrick(bricks[i]).ok) << bricks[i].id;
    test::runFor(world.get(), 0.5);
    ASSERT_EQ(test::snapshotOf(*world, "p2").state, BrickState::kStable);
    ASSERT_EQ(displacement(*world, "p2"), 0.0);
    ASSERT_TRUE(world->addBrick(bricks.back()).ok);
    test::runFor(world.get(), 2.0);
    if (tips) {
      EXPECT_GT(test::turn(*world, "p2"), 0.1);
    } else {
      EXPECT_EQ(test::snapshotOf(*world, "p2").state, BrickState::kStable);
      EXPECT_EQ(test::snapshotOf(*world, "plank").state, BrickState::kLeaning);
      EXPECT_EQ(displacement(*world, "p2"), 0.0);
      EXPECT_EQ(displacement(*world, "plank"), 0.0);
    }
    EXPECT_EQ(test::snapshotOf(*world, "p0").state, BrickState::kStable);
  }
}

TEST_P(StaticsInMode, CardHousesFromTheGeneratorStandStill) {
  // Every V at 20 degrees, far below its 46.9-degree threshold at mu 0.5;
  // each level brick rests on half of each of two apexes, its COM between
  // them. Placed all at once (interval 0) and V by V (interval 0.1 s).
  for (const int levels : {3, 4}) {
    for (const double interval : {0.0, 0.1}) {
      SCOPED_TRACE(std::to_string(levels) + " levels, interval " + std::to_string(interval));
      auto world = worldWithFriction(GetParam(), 0.5);
      CardHouseParams params;
      params.levels = levels;
      params.angle = 20.0 * M_PI / 180.0;
      params.interval = interval;
      std::vector<ScheduledBrick> house;
      ASSERT_TRUE(generateCardHouse(params, world->types(), &house).ok);
      // levels (levels + 1) / 2 V's of two, and a level brick fewer per row.
      ASSERT_EQ(house.size(),
                static_cast<std::size_t>(levels * (levels + 1) + (levels - 1) * levels / 2));
      std::size_t next = 0;
      for (double t = 0.0; next < house.size(); t += world->options().time_step) {
        for (; next < house.size() && house[next].at <= t; ++next) {
          const Status placed = world->addBrick(house[next].placement);
          ASSERT_TRUE(placed.ok) << house[next].placement.id << ": " << placed.message;
        }
        world->step();
      }
      test::runFor(world.get(), 1.0);
      for (const ScheduledBrick& b : house) {
        EXPECT_NE(test::snapshotOf(*world, b.placement.id).state, BrickState::kDynamic)
            << b.placement.id;
        EXPECT_EQ(displacement(*world, b.placement.id), 0.0) << b.placement.id;
      }
      // Every brick is in a leaning group (a level plank shares its V's),
      // and the groups' forces, passed from one to the next, hold them all.
      std::vector<std::string> ids;
      for (const ScheduledBrick& b : house) ids.push_back(b.placement.id);
      const test::ForceBalance balance = test::contactForceBalance(*world, ids);
      EXPECT_EQ(balance.bricks_with_forces, static_cast<int>(ids.size()));
      expectBalanced(balance);
    }
  }
}

TEST(PlainBullet, TwoLevelCardHouseIsReportedNotJudged) {
  // Plain Bullet cannot hold a V (docs/design.md, "The stability layer"); what it does is
  // reported for the record, not asserted.
  auto world = worldWithFriction("none", 0.5);
  for (const BrickPlacement& placement : twoLevelCardHouse())
    ASSERT_TRUE(world->addBrick(placement).ok) << placement.id;
  test::runFor(world.get(), 2.0);
  double worst = 0.0;
  for (const BrickPlacement& placement : twoLevelCardHouse())
    worst = std::max(worst, displacement(*world, placement.id));
  RecordProperty("none_worst_displacement_mm", std::to_string(1e3 * worst));
  std::printf("plain Bullet, 2-level card house after 2 s: worst displacement %.1f mm\n",
              1e3 * worst);
}

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

TEST_P(StaticsInMode, CounterweightedOverhangsFreezeWithZeroDrift) {
  // The stacks of RigidBlockStatics.CounterweightsHoldOverhangsThatFallWithoutThem.
  for (const std::vector<double>& x :
       {std::vector<double>{0.0, 0.7, 0.25}, std::vector<double>{0.0, 0.75, 0.35, 0.25}}) {
    auto world = flatStack(GetParam(), x, 2.0);
    for (std::size_t level = 0; level < x.size(); ++level) {
      const std::string id = "p" + std::to_string(level);
      EXPECT_EQ(test::snapshotOf(*world, id).state, BrickState::kStable)
          << id << " of " << x.size();
      EXPECT_EQ(displacement(*world, id), 0.0) << id << " of " << x.size();
    }
  }
}

TEST_P(StaticsInMode, OverhangsWithoutTheirLastCounterweightFall) {
  for (const std::vector<double>& x :
       {std::vector<double>{0.0, 0.7}, std::vector<double>{0.0, 0.75, 0.35}}) {
    auto world = flatStack(GetParam(), x, 2.0);
    // The overhanging plank tips over its base's edge until its end
    // reaches the table: its centre drops and it turns.
    const BrickSnapshot plank = test::snapshotOf(*world, "p1");
    EXPECT_LT(plank.pose.translation().z(), 1.5 * kKaplaThickness - 1e-3) << x.size();
    const double tilt = std::acos(std::min(1.0, plank.pose.linear()(2, 2)));
    EXPECT_GT(tilt, 0.05) << x.size();
    EXPECT_EQ(test::snapshotOf(*world, "p0").state, BrickState::kStable);
  }
}

TEST(EquilibriumWake, ATowerPastItsCollapseLayerWakesFromTheFailingBrickOnce) {
  // A slant tower of KAPLAs each 14 mm further along x, one every 0.25 s.
  // With layer k placed, the COM of layers 1..k sits 14 (k + 1) / 2 mm past
  // b0's centre, beyond its edge at L/2 = 58.5 mm from k = 8 (63 mm) on:
  // layers 1..8 tip about b0's edge as one, and no smaller set must move
  // (the COM of 2..8 sits 56 mm past b1's centre, inside). Statics' least
  // imbalance is the same couple on any of them: waking only the top brick,
  // which stands on the one under it, would freeze it again for ever. The
  // mechanism wakes at once; b0 is not in it (the falling bricks may shove
  // it later, as they do in plain Bullet at 1/4000 s and 100 iterations).
  auto world = test::worldWithFriction("equilibrium", 0.5);
  SlantTowerParams params;
  params.layers = 9;
  params.offset = 0.014;
  params.interval = 0.25;
  std::vector<ScheduledBrick> tower;
  ASSERT_TRUE(generateSlantTower(params, world->types(), &tower).ok);
  std::size_t next = 0;
  std::vector<SimEvent> events;
  for (double t = 0.0; t < 3.0; t += world->options().time_step) {
    for (; next < tower.size() && tower[next].at <= t; ++next)
      ASSERT_TRUE(world->addBrick(tower[next].placement).ok);
    world->step();
    const std::vector<SimEvent> now = world->takeEvents();
    events.insert(events.end(), now.begin(), now.end());
  }
  std::map<std::string, int> wakes;
  std::set<std::string> at_collapse;
  double collapse_time = -1.0;
  for (const SimEvent& e : events) {
    if (e.kind != SimEventKind::kWoken) continue;
    ++wakes[e.brick_id];
    if (collapse_time < 0.0) collapse_time = e.time;
    if (e.time == collapse_time) at_collapse.insert(e.brick_id);
  }
  EXPECT_EQ(at_collapse, (std::set<std::string>{"b1", "b2", "b3", "b4", "b5", "b6", "b7", "b8"}));
  for (const auto& [id, count] : wakes) {
    if (id != "b0") {
      EXPECT_EQ(count, 1) << id << " woken more than once";
    }
  }
  EXPECT_EQ(world->cost().wake_cycles, 0u);
  EXPECT_LT(displacement(*world, "b0"), 0.03);
  EXPECT_GT(displacement(*world, "b8"), 0.02);  // it fell
}

INSTANTIATE_TEST_SUITE_P(Modes, StaticsInMode, ::testing::ValuesIn(test::modelModes()));

}  // namespace
}  // namespace brick_stack_sim
