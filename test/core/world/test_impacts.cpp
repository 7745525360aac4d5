// Impacts on a settled tower (docs/design.md, "Impacts and held bricks";
// thesis 4.2): a brick thrown at a frozen 13-layer KAPLA tower. The
// stability layer judges the blow before
// Bullet's step, from the impulse against what holds the struck brick: a hit
// at the top moves the top layer and nothing two layers below; a hard hit low
// in the tower slides the struck brick in place under its load, and the tower
// stands; a touch of 5 cm/s moves nothing. None of it may depend on the time
// step, so every case runs at 1 ms and at 0.5 ms.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

constexpr int kLayers = 13;
/// The striker starts this far from the face it is thrown at [m], or
/// nearer when slow: it is to arrive before it has fallen visibly.
constexpr double kStartGap = 0.004;
constexpr double kFlightTime = 0.002;  ///< [s]
/// It flies this much higher than the layer it is thrown at [m]: a throw
/// exactly flush with the layer would catch the edges of the layers above
/// and below once gravity has pulled it down by a hair.
constexpr double kAimAbove = 0.0003;

struct ThrowCase {
  std::string mode;
  double time_step;  ///< [s]
};

std::string caseName(const testing::TestParamInfo<ThrowCase>& info) {
  return info.param.mode + "_" + std::to_string(std::lround(info.param.time_step * 1e6)) + "us";
}

/// Throws a KAPLA at the outer long face of brick slot 0 of `layer`, at
/// the layer's height, square to the face, at `speed` [m/s].
void throwKaplaAt(BrickWorld* world, int layer, double speed) {
  const test::TowerSlot slot = test::towerSlot(layer, 0);
  // Even layers lie along x at y = -offset: the face looks to -y, and the
  // striker flies along +y lying parallel to it. Odd layers turned by 90.
  const bool along_x = layer % 2 == 0;
  const Eigen::Vector3d inward = along_x ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const double face = -test::kTowerOffset - test::kKaplaWidth / 2;
  const double start = face - test::kKaplaWidth / 2 - std::min(kStartGap, speed * kFlightTime);
  BrickPlacement striker = test::placement(
      "striker",
      Eigen::Vector3d(along_x ? 0.0 : start, along_x ? start : 0.0, slot.z + kAimAbove),
      slot.yaw);
  striker.linear_velocity = speed * inward;
  ASSERT_TRUE(world->addBrick(striker).ok);
}

/// How far tower brick `index` of `world` has moved from where it was placed [m].
double towerDisplacement(const BrickWorld& world, int index) {
  BrickSnapshot brick;
  EXPECT_TRUE(world.find("t" + std::to_string(index), &brick));
  return (brick.pose.translation() - brick.placed_pose.translation()).norm();
}

class TowerImpact : public testing::TestWithParam<ThrowCase> {
 protected:
  void SetUp() override {
    WorldOptions options = test::optionsFor(GetParam().mode);
    options.time_step = GetParam().time_step;
    world_ = test::makeWorld(options);
    for (int i = 0; i < 2 * kLayers; ++i) ASSERT_TRUE(world_->addBrick(test::towerBrick(i)).ok);
    for (const BrickSnapshot& brick : world_->snapshot())
      ASSERT_EQ(brick.state, BrickState::kStable) << brick.id << " did not freeze when placed";
    world_->takeEvents();
  }

  void throwAt(int layer, double speed) { throwKaplaAt(world_.get(), layer, speed); }

  double displacement(int index) const { return towerDisplacement(*world_, index); }

  /// Events of `kind` so far, in order.
  std::vector<SimEvent> eventsOf(SimEventKind kind) {
    std::vector<SimEvent> all = world_->takeEvents();
    seen_.insert(seen_.end(), all.begin(), all.end());
    std::vector<SimEvent> found;
    for (const SimEvent& event : seen_)
      if (event.kind == kind) found.push_back(event);
    return found;
  }

  std::unique_ptr<BrickWorld> world_;
  std::vector<SimEvent> seen_;
};

TEST_P(TowerImpact, HitAtTheTopMovesTheTopLayerAndNothingTwoLayersBelow) {
  const int top = kLayers - 1;
  throwAt(top, 1.0);
  test::runFor(world_.get(), 1.0);
  EXPECT_GT(displacement(2 * top), 0.003) << "the struck top brick did not move";
  for (int index = 0; index < 2 * (top - 1); ++index)
    EXPECT_LT(displacement(index), 0.001) << "t" << index << ", layer " << index / 2;
  const std::vector<SimEvent> impacts = eventsOf(SimEventKind::kImpact);
  ASSERT_FALSE(impacts.empty());
  EXPECT_EQ(impacts.front().brick_id, "t" + std::to_string(2 * top));
  EXPECT_NE(impacts.front().reason.find("mJ"), std::string::npos) << impacts.front().reason;
}

TEST_P(TowerImpact, HardHitAtLayerThreeSlidesTheHitBrickAndTheTowerStands) {
  throwAt(3, 3.0);
  test::runFor(world_.get(), 1.0);
  EXPECT_GT(displacement(6), 0.003) << "the struck brick of layer 3 did not move";
  // The tower stands: every other brick is where it was, layers above the
  // hit included (the deformation is in the struck brick, thesis 4.2).
  for (int index = 0; index < 2 * kLayers; ++index) {
    if (index == 6) continue;
    EXPECT_LT(displacement(index), 0.001) << "t" << index << ", layer " << index / 2;
  }
  for (const BrickSnapshot& brick : world_->snapshot())
    if (brick.id != "striker") {
      EXPECT_NE(brick.state, BrickState::kDynamic) << brick.id;
    }
}

TEST_P(TowerImpact, GentleTouchMovesNothing) {
  throwAt(kLayers - 1, 0.05);
  test::runFor(world_.get(), 1.0);
  for (int index = 0; index < 2 * kLayers; ++index)
    EXPECT_EQ(displacement(index), 0.0) << "t" << index;
  EXPECT_TRUE(eventsOf(SimEventKind::kWoken).empty());
}

TEST_P(TowerImpact, ATouchOfAFewCentimetresASecondIsJudgedAndAbsorbed) {
  // Above the impact speed, so the rule judges it: a KAPLA at 8 cm/s gives
  // the top brick 4 cm/s, a slide of 0.16 mm, under the visible 0.5 mm.
  throwAt(kLayers - 1, 0.08);
  test::runFor(world_.get(), 1.0);
  for (int index = 0; index < 2 * kLayers; ++index)
    EXPECT_EQ(displacement(index), 0.0) << "t" << index;
  EXPECT_TRUE(eventsOf(SimEventKind::kWoken).empty());
  const std::vector<SimEvent> impacts = eventsOf(SimEventKind::kImpact);
  ASSERT_FALSE(impacts.empty());
  EXPECT_EQ(impacts.front().brick_id, "t" + std::to_string(2 * (kLayers - 1)));
  EXPECT_NE(impacts.front().reason.find("absorbed"), std::string::npos) << impacts.front().reason;
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, TowerImpact,
                         testing::Values(ThrowCase{"com", 1e-3}, ThrowCase{"com", 5e-4},
                                         ThrowCase{"equilibrium", 1e-3},
                                         ThrowCase{"equilibrium", 5e-4}),
                         caseName);

class FastThrow : public testing::TestWithParam<std::string> {};

TEST_P(FastThrow, APlankAtAnyAcceptedSpeedHitsWhatIsInItsWay) {
  // A KAPLA flies 10 to 50 mm in a 1 ms step, more than the 23.4 mm width
  // of the plank it is thrown at: judged only where it ends a step it would
  // pass through it. Momentum says the struck plank, of the striker's mass,
  // is driven on along the throw; the striker does not come out beyond the
  // tower while the struck plank is still in its way. A brick thrown at the
  // speed limit is no numerical blow-up. A touch at 5 cm/s moves nothing
  // of the frozen tower (plain Bullet's tower creeps by itself: 2 mm).
  for (const double speed : {0.05, 10.0, 30.0, 50.0}) {
    SCOPED_TRACE(std::to_string(speed) + " m/s");
    WorldOptions options = test::optionsFor(GetParam());
    ASSERT_EQ(options.max_linear_speed, 50.0);
    auto world = test::makeWorld(options);
    for (int i = 0; i < 2 * kLayers; ++i) ASSERT_TRUE(world->addBrick(test::towerBrick(i)).ok);
    throwKaplaAt(world.get(), 3, speed);
    const Eigen::Vector3d placed = test::towerBrick(6).pose.translation();
    test::runFor(world.get(), 0.01);
    BrickSnapshot struck;
    ASSERT_TRUE(world->find("t6", &struck));
    BrickSnapshot striker;
    const bool striker_here = world->find("striker", &striker);
    EXPECT_EQ(world->cost().blowups, 0u);
    EXPECT_EQ(world->cost().nonfinite, 0u);
    if (speed < 1.0) {
      test::runFor(world.get(), 1.0);
      for (int index = 0; index < 2 * kLayers; ++index)
        EXPECT_LT(towerDisplacement(*world, index), GetParam() == "none" ? 0.002 : 1e-12)
            << "t" << index;
      continue;
    }
    // Layer 3 lies along y at x = -offset; the throw is along +x.
    EXPECT_GT(struck.pose.translation().x() - placed.x(), 0.005) << "the struck plank did not move";
    if (striker_here) {
      EXPECT_LT(striker.pose.translation().x(), struck.pose.translation().x())
          << "the striker passed the plank it struck";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, FastThrow, testing::ValuesIn(availableStabilityModes()));

}  // namespace
}  // namespace brick_stack_sim
