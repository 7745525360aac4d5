// Held bricks (docs/design.md, "Impacts and held bricks"): a brick taken
// into a hand is kinematic, follows its target no faster than the held
// speed limits, and pushes the stack through
// the impact model; let go, it falls, settles and may join the stack. Bad
// requests are refused and change nothing.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"
#include "support/modes.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::Isometry3d poseAt(const Eigen::Vector3d& position, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = position;
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

BrickSnapshot brickOf(const BrickWorld& world, const std::string& id) {
  BrickSnapshot brick;
  EXPECT_TRUE(world.find(id, &brick)) << id;
  return brick;
}

double displacement(const BrickSnapshot& brick) {
  return (brick.pose.translation() - brick.placed_pose.translation()).norm();
}

class HeldBrick : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { world_ = test::makeWorld(test::optionsFor(GetParam())); }

  /// A frozen two-per-layer tower of `layers` (ids t0, t1, ...).
  void buildTower(int layers) {
    for (int i = 0; i < 2 * layers; ++i) ASSERT_TRUE(world_->addBrick(test::towerBrick(i)).ok);
    test::runFor(world_.get(), 0.05);
  }

  std::unique_ptr<BrickWorld> world_;
};

TEST_P(HeldBrick, FollowsItsTargetNoFasterThanTheLimit) {
  const Eigen::Vector3d start(0.3, 0.2, kKaplaThickness / 2);
  ASSERT_TRUE(world_->addBrick(test::placement("hand", start)).ok);
  test::runFor(world_.get(), 0.1);
  ASSERT_TRUE(world_->graspBrick("hand").ok);
  EXPECT_EQ(brickOf(*world_, "hand").state, BrickState::kHeld);
  EXPECT_EQ(world_->heldBrick(), "hand");
  const Eigen::Isometry3d target = poseAt(start + Eigen::Vector3d(-0.2, 0.0, 0.1), M_PI / 2);
  ASSERT_TRUE(world_->setHeldTarget(target).ok);
  const double limit = world_->options().held.max_linear_speed;
  test::runFor(world_.get(), 0.1);
  const BrickSnapshot moving = brickOf(*world_, "hand");
  const double travelled = (moving.pose.translation() - start).norm();
  EXPECT_LE(travelled, limit * 0.1 + 1e-9);
  EXPECT_GT(travelled, 0.9 * limit * 0.1) << "it should move at the limit toward a far target";
  EXPECT_NEAR(moving.linear_velocity.norm(), limit, 1e-6);
  test::runFor(world_.get(), 1.0);
  const BrickSnapshot there = brickOf(*world_, "hand");
  EXPECT_LT((there.pose.translation() - target.translation()).norm(), 1e-9);
  EXPECT_TRUE(there.pose.linear().isApprox(target.linear(), 1e-9));
  EXPECT_EQ(there.state, BrickState::kHeld);
}

TEST_P(HeldBrick, BadRequestsAreRefusedAndChangeNothing) {
  buildTower(2);
  ASSERT_TRUE(world_->addBrick(test::placement("loose", {0.3, 0.0, kKaplaThickness / 2})).ok);
  test::runFor(world_.get(), 0.1);
  std::string before = test::fingerprint(*world_);
  auto refused = [&](const Status& status, const std::string& expected) {
    EXPECT_FALSE(status.ok);
    EXPECT_NE(status.message.find(expected), std::string::npos)
        << "'" << status.message << "' does not mention '" << expected << "'";
    EXPECT_TRUE(test::fingerprint(*world_) == before) << status.message;
  };
  refused(world_->graspBrick("ghost"), "no brick");
  refused(world_->setHeldTarget(poseAt({0, 0, 0.1})), "no brick is held");
  refused(world_->releaseBrick("loose", Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()),
          "not held");
  refused(world_->releaseBrick("ghost", Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()),
          "no brick");
  if (GetParam() != "none") {
    // t0 carries layer 1, frozen on it.
    refused(world_->graspBrick("t0"), "carries t2, t3");
  }

  ASSERT_TRUE(world_->graspBrick("loose").ok);
  world_->step();
  before = test::fingerprint(*world_);  // holding it now
  refused(world_->graspBrick("t3"), "already held");
  refused(world_->graspBrick("loose"), "already held");
  refused(world_->setHeldTarget(poseAt({kNaN, 0, 0.1})), "not finite");
  Eigen::Isometry3d skewed = poseAt({0.3, 0, 0.1});
  skewed.linear()(0, 0) = 2.0;
  refused(world_->setHeldTarget(skewed), "rotation");
  refused(world_->setHeldTarget(poseAt({0.3, 0, 0.0})), "below the table top");
  refused(world_->releaseBrick("loose", {kNaN, 0, 0}, Eigen::Vector3d::Zero()), "not finite");
  refused(world_->releaseBrick("loose", {100, 0, 0}, Eigen::Vector3d::Zero()),
          "linear speed 100 m/s, over the limit of 50 m/s");
  refused(world_->applyImpulse("loose", {0.001, 0, 0}, {0.3, 0, 0.0039}), "is held");
  EXPECT_TRUE(world_->checkInvariants().ok) << world_->checkInvariants().message;
}

TEST_P(HeldBrick, SetDownGentlyOnATowerItJoinsIt) {
  if (GetParam() == "none") GTEST_SKIP() << "no stack to join in plain Bullet";
  const int layers = 6;
  buildTower(layers);
  const test::TowerSlot slot = test::towerSlot(layers, 0);
  ASSERT_TRUE(world_->addBrick(test::placement("hand", {0.3, 0.0, kKaplaThickness / 2})).ok);
  test::runFor(world_.get(), 0.1);
  ASSERT_TRUE(world_->graspBrick("hand").ok);
  // Over its slot, 3 cm up, then lowered at 2 cm/s to 1 mm under where it
  // would rest: the tower stops the hand.
  const Eigen::Vector3d over(slot.x, slot.y, slot.z + 0.03);
  ASSERT_TRUE(world_->setHeldTarget(poseAt(over, slot.yaw)).ok);
  test::runFor(world_.get(), 1.5);
  for (double z = over.z(); z > slot.z - 0.001; z -= 0.02 * 0.01) {
    ASSERT_TRUE(world_->setHeldTarget(poseAt({slot.x, slot.y, z}, slot.yaw)).ok);
    test::runFor(world_.get(), 0.01);
  }
  const BrickSnapshot resting = brickOf(*world_, "hand");
  EXPECT_NEAR(resting.pose.translation().z(), slot.z, 2e-4) << "the hand passed into the tower";
  ASSERT_TRUE(world_->releaseBrick("hand", Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()).ok);
  test::runFor(world_.get(), 0.5);
  const BrickSnapshot joined = brickOf(*world_, "hand");
  EXPECT_EQ(joined.state, BrickState::kStable);
  EXPECT_NEAR(joined.pose.translation().z(), slot.z, 2e-4);
  for (int i = 0; i < 2 * layers; ++i)
    EXPECT_LT(displacement(brickOf(*world_, "t" + std::to_string(i))), 1e-6) << "t" << i;
}

TEST_P(HeldBrick, SweptThroughATowerItKnocksBricksOff) {
  const int layers = 8;
  buildTower(layers);
  // Standing clear of the tower, turned across the sweep, at layer 4's height.
  const double z = test::towerSlot(4, 0).z;
  ASSERT_TRUE(
      world_->addBrick(test::placement("hand", {-0.2, 0.0, kKaplaThickness / 2}, M_PI / 2)).ok);
  test::runFor(world_.get(), 0.1);
  ASSERT_TRUE(world_->graspBrick("hand").ok);
  ASSERT_TRUE(world_->setHeldTarget(poseAt({-0.2, 0.0, z}, M_PI / 2)).ok);
  test::runFor(world_.get(), 0.5);
  world_->takeEvents();
  ASSERT_EQ(world_->options().held.max_linear_speed, 0.5);
  ASSERT_TRUE(world_->setHeldTarget(poseAt({0.2, 0.0, z}, M_PI / 2)).ok);
  test::runFor(world_.get(), 2.0);
  int knocked = 0;
  for (int i = 0; i < 2 * layers; ++i)
    knocked += displacement(brickOf(*world_, "t" + std::to_string(i))) > 0.02;
  EXPECT_GE(knocked, 4) << "a sweep at 0.5 m/s through layer 4 must knock bricks off";
  if (GetParam() != "none") {
    // The bricks below the sweep stay where they were (plain Bullet lets
    // the whole tower sway and creep).
    for (int i = 0; i < 2 * 3; ++i)
      EXPECT_LT(displacement(brickOf(*world_, "t" + std::to_string(i))), 0.001) << "t" << i;
    const std::vector<SimEvent> events = world_->takeEvents();
    EXPECT_TRUE(std::any_of(events.begin(), events.end(), [](const SimEvent& e) {
      return e.kind == SimEventKind::kImpact && e.reason.find("pushed by held hand") == 0;
    }));
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, HeldBrick, testing::ValuesIn(test::allModes()));

}  // namespace
}  // namespace brick_stack_sim
