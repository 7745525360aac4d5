// The builder's ledger, fed by hand: when a placed brick counts as at rest,
// as fallen, as knocked or as shifted in place by a throw, and what a build that should stand or
// collapse reports. No master: the builder feeds it what ~get_bricks returns.
#include <gtest/gtest.h>

#include "brick_stack_sim/planner/build_ledger.h"

namespace brick_stack_sim {
namespace planner {
namespace {

Eigen::Isometry3d at(double x, double y, double z, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

ObservedBrick seen(const std::string& id, const Eigen::Isometry3d& pose, bool frozen = true) {
  ObservedBrick brick;
  brick.id = id;
  brick.pose = pose;
  brick.frozen = frozen;
  return brick;
}

TEST(BuildLedger, AFrozenBrickWhereItWasPlacedStands) {
  BuildLedger ledger;
  ledger.recordPlaced("a", at(0, 0, 0.0039), 0.0, false);
  EXPECT_TRUE(ledger.observe(0.1, {seen("a", at(0, 0, 0.0039))}).empty());
  EXPECT_EQ(ledger.find("a")->fate, BrickFate::kStanding);
  const BuildSummary summary = ledger.summary();
  EXPECT_EQ(summary.placed, 1);
  EXPECT_EQ(summary.standing, 1);
  EXPECT_EQ(summary.frozen, 1);
  std::string verdict;
  EXPECT_TRUE(ledger.met(ExpectedOutcome::kStands, &verdict)) << verdict;
  EXPECT_FALSE(ledger.met(ExpectedOutcome::kCollapses, &verdict));
  EXPECT_NE(verdict.find("expects a collapse"), std::string::npos) << verdict;
}

TEST(BuildLedger, AMovingBrickRestsOnlyWhenSlowAndStillOverTwoLooks) {
  BuildLedger ledger;
  // Dropped from 1 cm: it lands 1 cm lower, which is where it was meant to go.
  ledger.recordPlaced("a", at(0, 0, 0.0139), 0.0, false);
  ObservedBrick falling = seen("a", at(0, 0, 0.0100), false);
  falling.linear_velocity = Eigen::Vector3d(0, 0, -0.3);
  ledger.observe(0.03, {falling});
  EXPECT_EQ(ledger.find("a")->fate, BrickFate::kUnsettled);
  ObservedBrick landed = seen("a", at(0, 0, 0.0039), false);
  ledger.observe(0.1, {landed});
  EXPECT_EQ(ledger.find("a")->fate, BrickFate::kUnsettled) << "one still look is not enough";
  ledger.observe(0.2, {landed});
  EXPECT_EQ(ledger.find("a")->fate, BrickFate::kStanding);
  std::string verdict;
  EXPECT_TRUE(ledger.met(ExpectedOutcome::kStands, &verdict)) << verdict;
}

TEST(BuildLedger, ABrickThatComesToRestAsideOrTurnedHasFallen) {
  BuildLedger ledger;
  ledger.recordPlaced("aside", at(0, 0, 0.05), 0.0, false);
  ledger.recordPlaced("turned", at(0.2, 0, 0.05), 0.0, false);
  const std::vector<const LedgerEntry*> fell = ledger.observe(
      1.0, {seen("aside", at(0.03, 0, 0.0039)), seen("turned", at(0.2, 0, 0.0039, 0.5))});
  ASSERT_EQ(fell.size(), 2u);
  EXPECT_NE(fell[0]->how.find("30.0 mm aside"), std::string::npos) << fell[0]->how;
  EXPECT_NE(fell[1]->how.find("turned 29 deg"), std::string::npos) << fell[1]->how;
}

TEST(BuildLedger, NamesTheFirstBrickToFallAndWhenInTheBuild) {
  BuildLedger ledger;
  ledger.recordPlaced("b0", at(0, 0, 0.0039), 0.0, false);
  ledger.recordPlaced("b1", at(0.011, 0, 0.0117), 1.0, false);
  ledger.observe(1.1, {seen("b0", at(0, 0, 0.0039)), seen("b1", at(0.011, 0, 0.0117))});
  ledger.recordPlaced("b2", at(0.022, 0, 0.0195), 2.0, false);
  // b1 moves 4.9 mm: still standing; then 6 mm: fallen, after 3 placements.
  EXPECT_TRUE(
      ledger
          .observe(2.1, {seen("b0", at(0, 0, 0.0039)), seen("b1", at(0.0159, 0, 0.0117), false),
                         seen("b2", at(0.022, 0, 0.0195))})
          .empty());
  const auto fell =
      ledger.observe(2.2, {seen("b0", at(0, 0, 0.0039)), seen("b1", at(0.017, 0, 0.0117), false),
                           seen("b2", at(0.022, 0, 0.0195))});
  ASSERT_EQ(fell.size(), 1u);
  EXPECT_EQ(fell[0]->id, "b1");
  EXPECT_EQ(fell[0]->placed_when_fell, 3);
  EXPECT_DOUBLE_EQ(fell[0]->fell_at, 2.2);
  EXPECT_FALSE(fell[0]->fell_after_throw);
  std::string verdict;
  EXPECT_FALSE(ledger.met(ExpectedOutcome::kStands, &verdict));
  EXPECT_NE(verdict.find("brick b1 (placement 2) moved 6.0 mm"), std::string::npos) << verdict;
  EXPECT_NE(verdict.find("after 3 placements"), std::string::npos) << verdict;
  EXPECT_TRUE(ledger.met(ExpectedOutcome::kCollapses, &verdict)) << verdict;
  const BuildSummary summary = ledger.summary();
  EXPECT_EQ(summary.standing, 2);
  EXPECT_EQ(summary.fallen, 1);
}

TEST(BuildLedger, WhatFallsAfterAThrowIsKnockedNotAFailedBuild) {
  BuildLedger ledger;
  ledger.recordPlaced("b0", at(0, 0, 0.0039), 0.0, false);
  ledger.recordPlaced("b1", at(0, 0, 0.0117), 0.5, false);
  ledger.observe(0.6, {seen("b0", at(0, 0, 0.0039)), seen("b1", at(0, 0, 0.0117))});
  ledger.recordPlaced("striker", at(0, -0.03, 0.0117), 1.0, true);
  // b1 is thrown off b0 onto the table: 7.8 mm lower, no longer on b0.
  const auto fell =
      ledger.observe(1.1, {seen("b0", at(0, 0, 0.0039)), seen("b1", at(0, 0.08, 0.0039), false),
                           seen("striker", at(0, -0.1, -0.5), false)});
  ASSERT_EQ(fell.size(), 1u) << "the thrown brick itself is never judged";
  EXPECT_EQ(fell[0]->id, "b1");
  EXPECT_EQ(fell[0]->fate, BrickFate::kFallen);
  EXPECT_TRUE(fell[0]->fell_after_throw);
  const BuildSummary summary = ledger.summary();
  EXPECT_EQ(summary.placed, 3);
  EXPECT_EQ(summary.standing, 1);
  EXPECT_EQ(summary.knocked, 1);
  EXPECT_EQ(summary.fallen, 0);
  EXPECT_EQ(summary.thrown, 1);
  std::string verdict;
  EXPECT_TRUE(ledger.met(ExpectedOutcome::kStands, &verdict)) << verdict;
}

TEST(BuildLedger, APlankAThrowSlidesAlongItsLayerStandsShiftedNotKnocked) {
  // impact_layer3: a plank of layer 3 struck at 3 m/s slides 11 mm along its
  // layer, still resting on layer 2 at its height: it never left the tower.
  BuildLedger ledger;
  ledger.recordPlaced("b4", at(0, 0, 0.0195), 0.0, false);
  ledger.observe(0.1, {seen("b4", at(0, 0, 0.0195))});
  ledger.recordPlaced("striker", at(0, -0.2, 0.0195), 1.0, true);
  const auto changed = ledger.observe(1.1, {seen("b4", at(0, 0.011, 0.0195, 0.02), false)});
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0]->fate, BrickFate::kStanding);
  EXPECT_TRUE(changed[0]->shifted);
  EXPECT_NE(changed[0]->how.find("moved 11.0 mm"), std::string::npos) << changed[0]->how;
  EXPECT_TRUE(ledger.observe(1.2, {seen("b4", at(0, 0.011, 0.0195, 0.02))}).empty())
      << "a shift is told once";
  BuildSummary summary = ledger.summary();
  EXPECT_EQ(summary.knocked, 0);
  EXPECT_EQ(summary.standing, 1);
  EXPECT_EQ(summary.shifted, 1);
  EXPECT_NE(formatSummary("s", summary, 2.0).find("standing 1 (1 shifted), fallen 0, knocked 0"),
            std::string::npos)
      << formatSummary("s", summary, 2.0);
  std::string verdict;
  EXPECT_TRUE(ledger.met(ExpectedOutcome::kStands, &verdict)) << verdict;
  // If it later drops off its layer (by more than fall_distance), it is knocked.
  const auto fell = ledger.observe(1.5, {seen("b4", at(0, 0.06, 0.0117), false)});
  ASSERT_EQ(fell.size(), 1u);
  EXPECT_EQ(fell[0]->fate, BrickFate::kFallen);
  summary = ledger.summary();
  EXPECT_EQ(summary.knocked, 1);
  EXPECT_EQ(summary.shifted, 0);
}

TEST(BuildLedger, TheSameSlideWithoutAThrowIsAFall) {
  BuildLedger ledger;
  ledger.recordPlaced("b4", at(0, 0, 0.0195), 0.0, false);
  ledger.observe(0.1, {seen("b4", at(0, 0, 0.0195))});
  const auto fell = ledger.observe(1.1, {seen("b4", at(0, 0.011, 0.0195), false)});
  ASSERT_EQ(fell.size(), 1u);
  EXPECT_EQ(fell[0]->fate, BrickFate::kFallen);
  EXPECT_FALSE(fell[0]->fell_after_throw);
  EXPECT_EQ(ledger.summary().fallen, 1);
}

TEST(BuildLedger, LeaningAndStableFrozenBricksAreCountedApart) {
  // A V of two leaning planks with a level plank across its apex.
  BuildLedger ledger;
  ledger.recordPlaced("left", at(-0.02, 0, 0.055), 0.0, false);
  ledger.recordPlaced("right", at(0.02, 0, 0.055), 0.0, false);
  ledger.recordPlaced("top", at(0, 0, 0.115), 1.0, false);
  ObservedBrick left = seen("left", at(-0.02, 0, 0.055));
  ObservedBrick right = seen("right", at(0.02, 0, 0.055));
  left.leaning = right.leaning = true;
  ledger.observe(1.5, {left, right, seen("top", at(0, 0, 0.115))});
  const BuildSummary summary = ledger.summary();
  EXPECT_EQ(summary.standing, 3);
  EXPECT_EQ(summary.frozen, 3);
  EXPECT_EQ(summary.leaning, 2);
  EXPECT_NE(formatSummary("v", summary, 2.0).find("frozen 3 (stable 1, leaning 2)"),
            std::string::npos)
      << formatSummary("v", summary, 2.0);
}

TEST(BuildLedger, RemovedFellOffRefusedAndNeverRestedAreAccountedFor) {
  BuildLedger ledger;
  ledger.recordPlaced("gone", at(0, 0, 0.0039), 0.0, false);
  ledger.recordPlaced("off", at(0.5, 0, 0.0039), 0.0, false);
  ledger.recordPlaced("rolling", at(-0.3, 0, 0.0039), 0.0, false);
  ledger.recordRefused("overlap", "overlaps gone");
  ObservedBrick off = seen("off", at(0.7, 0, -0.3), false);
  off.fell_off = true;
  ObservedBrick rolling = seen("rolling", at(-0.3, 0, 0.0039), false);
  rolling.angular_velocity = Eigen::Vector3d(0, 3, 0);
  const auto fell = ledger.observe(1.0, {off, rolling});
  ASSERT_EQ(fell.size(), 2u);
  EXPECT_EQ(fell[0]->how, "was removed from the simulation");
  EXPECT_EQ(fell[1]->how, "fell off the table");
  const BuildSummary summary = ledger.summary();
  EXPECT_EQ(summary.placed, 3);
  EXPECT_EQ(summary.fallen, 2);
  EXPECT_EQ(summary.unsettled, 1);
  EXPECT_EQ(summary.refused, 1);
  EXPECT_EQ(summary.placed, summary.standing + summary.fallen + summary.knocked +
                                summary.unsettled + summary.thrown);
  EXPECT_EQ(formatSummary("s", summary, 1.0),
            "demo summary: scene s, placed 3, standing 0, fallen 2, knocked 0, unsettled 1, "
            "refused 1, thrown 0, frozen 0 (stable 0, leaning 0), t=1.0 s");
}

TEST(BuildLedger, ARefusedOrRestlessBrickFailsABuildThatShouldStand) {
  std::string verdict;
  BuildLedger refused;
  refused.recordRefused("b3", "overlaps b2 by 4 mm");
  EXPECT_FALSE(refused.met(ExpectedOutcome::kStands, &verdict));
  EXPECT_NE(verdict.find("refused brick b3: overlaps b2"), std::string::npos) << verdict;
  BuildLedger restless;
  restless.recordPlaced("b0", at(0, 0, 0.0039), 0.0, false);
  EXPECT_FALSE(restless.met(ExpectedOutcome::kStands, &verdict));
  EXPECT_NE(verdict.find("b0 never came to rest"), std::string::npos) << verdict;
}

}  // namespace
}  // namespace planner
}  // namespace brick_stack_sim
