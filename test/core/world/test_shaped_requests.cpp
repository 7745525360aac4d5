// Requests on bricks that are not boxes: the overlap check, the world's
// table top, pushes on curved faces, placement queries and the hand, each
// against geometry worked out by hand.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"
#include "support/shapes.h"

namespace brick_stack_sim {
namespace {

constexpr double kRadius = 0.02, kLength = 0.05;

class ShapedRequests : public ::testing::Test {
 protected:
  void SetUp() override {
    BrickTypeLibrary types = test::packageTypes();
    ASSERT_TRUE(types.add(test::cylinderType("can", kRadius, kLength, 0.1)).ok);
    ASSERT_TRUE(BrickWorld::create(test::optionsFor("com"), types, &world_).ok);
    ASSERT_TRUE(world_->addBrick(canAt("base", Eigen::Vector3d(0, 0, kLength / 2))).ok);
  }

  static BrickPlacement canAt(const std::string& id, const Eigen::Vector3d& position) {
    BrickPlacement p;
    p.id = id;
    p.type = "can";
    p.pose.translation() = position;
    return p;
  }

  std::unique_ptr<BrickWorld> world_;
};

TEST_F(ShapedRequests, CylindersOverlapByTheirRoundSidesNotTheirBoundingBoxes) {
  // Two cans side by side 41 mm apart: their circles (radius 20 mm) miss by
  // 1 mm. At 39 mm they overlap by 1 mm and are refused.
  EXPECT_TRUE(world_->checkPlacement(canAt("near", Eigen::Vector3d(0.041, 0, kLength / 2))).ok);
  const Status overlapping =
      world_->checkPlacement(canAt("in", Eigen::Vector3d(0.039, 0, kLength / 2)));
  EXPECT_FALSE(overlapping.ok);
  EXPECT_NE(overlapping.message.find("overlaps brick 'base'"), std::string::npos)
      << overlapping.message;
  // Diagonally at 30 mm along x and y their bounding squares overlap by 10 mm,
  // but the centres lie 42.4 mm apart: the circles do not touch.
  EXPECT_TRUE(world_->checkPlacement(canAt("corner", Eigen::Vector3d(0.03, 0.03, kLength / 2))).ok);
}

TEST_F(ShapedRequests, NoPointOfACylinderMayGoUnderTheTable) {
  // Lying, a can reaches its radius below its centre.
  BrickPlacement lying = canAt("lying", Eigen::Vector3d(0.1, 0, kRadius - 0.001));
  lying.pose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Status under = world_->checkPlacement(lying);
  EXPECT_FALSE(under.ok);
  EXPECT_NE(under.message.find("below the table top"), std::string::npos) << under.message;
  lying.pose.translation().z() = kRadius;
  EXPECT_TRUE(world_->checkPlacement(lying).ok);
}

TEST_F(ShapedRequests, APushActsOnTheCurvedSideAndNotBesideIt) {
  // On its side at 20 mm from the axis; 3 mm out is beyond the 1 mm allowed.
  EXPECT_TRUE(world_
                  ->applyImpulse("base", Eigen::Vector3d(1e-4, 0, 0),
                                 Eigen::Vector3d(-kRadius * std::cos(0.3), -kRadius * std::sin(0.3),
                                                 kLength / 2))
                  .ok);
  const Status beside = world_->applyImpulse(
      "base", Eigen::Vector3d(1e-4, 0, 0),
      Eigen::Vector3d(-0.023 * std::cos(0.3), -0.023 * std::sin(0.3), kLength / 2));
  EXPECT_FALSE(beside.ok);
  EXPECT_NE(beside.message.find("outside brick"), std::string::npos) << beside.message;
}

TEST_F(ShapedRequests, ACanOnACanStandsAndOneOverhangingItsRimDoesNot) {
  // A can on the base can's cap: centred it stands; shifted by 25 mm its
  // centre lies beyond the cap's rim (20 mm) and it would fall.
  PlacementReport report;
  ASSERT_TRUE(
      world_->evaluatePlacement(canAt("top", Eigen::Vector3d(0, 0, 1.5 * kLength)), &report).ok);
  EXPECT_TRUE(report.stable) << report.reason;
  ASSERT_EQ(report.supported_by.size(), 1u);
  EXPECT_EQ(report.supported_by[0], "base");
  // The cap is a disc of 20 mm radius: the margin is its distance to the rim,
  // within the prism's facets' sag.
  EXPECT_NEAR(report.margin, kRadius, kCylinderFacetSag);
  ASSERT_TRUE(
      world_->evaluatePlacement(canAt("off", Eigen::Vector3d(0.025, 0, 1.5 * kLength)), &report)
          .ok);
  EXPECT_FALSE(report.stable);
}

TEST_F(ShapedRequests, AHeldCanIsSetDownOnTheTableAndStands) {
  ASSERT_TRUE(world_->addBrick(canAt("hand", Eigen::Vector3d(0.1, 0, kLength / 2 + 0.03))).ok);
  ASSERT_TRUE(world_->graspBrick("hand").ok);
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.translation() = Eigen::Vector3d(0.1, 0, kLength / 2);
  ASSERT_TRUE(world_->setHeldTarget(target).ok);
  test::runFor(world_.get(), 0.5);
  ASSERT_TRUE(world_->releaseBrick("hand", Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()).ok);
  test::runFor(world_.get(), 0.5);
  BrickSnapshot hand;
  ASSERT_TRUE(world_->find("hand", &hand));
  EXPECT_EQ(hand.state, BrickState::kStable);
  EXPECT_NEAR(hand.pose.translation().z(), kLength / 2, 1e-4);
}

}  // namespace
}  // namespace brick_stack_sim
