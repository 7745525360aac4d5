// Cylinders, wedges and planks of other shapes in a running world, against
// statics and mechanics worked out by hand in each test.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"
#include "support/modes.h"
#include "support/shapes.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaThickness;
using test::kKaplaWidth;

/// A roof: a triangular prism lying on its base, `base` wide along x, `height`
/// high, `depth` along y; its frame's origin in the middle of its base.
BrickType roofType(double base, double height, double depth, double mass) {
  std::vector<Eigen::Vector3d> vertices;
  for (double y : {-depth / 2, depth / 2}) {
    vertices.emplace_back(-base / 2, y, 0.0);
    vertices.emplace_back(base / 2, y, 0.0);
    vertices.emplace_back(0.0, y, height);
  }
  return test::convexType("roof", vertices, mass);
}

std::unique_ptr<BrickWorld> worldWith(const std::string& mode,
                                      const std::vector<BrickType>& extra) {
  BrickTypeLibrary types = test::packageTypes();
  for (const BrickType& type : extra) EXPECT_TRUE(types.add(type).ok) << type.name;
  std::unique_ptr<BrickWorld> world;
  EXPECT_TRUE(BrickWorld::create(test::optionsFor(mode), types, &world).ok);
  return world;
}

BrickPlacement at(const std::string& id, const std::string& type, const Eigen::Vector3d& position,
                  const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  BrickPlacement p;
  p.id = id;
  p.type = type;
  p.pose.translation() = position;
  p.pose.linear() = rotation;
  return p;
}

BrickSnapshot brick(const BrickWorld& world, const std::string& id) {
  BrickSnapshot snapshot;
  EXPECT_TRUE(world.find(id, &snapshot)) << id;
  return snapshot;
}

class ShapesInMode : public ::testing::TestWithParam<std::string> {};

// A cylinder of radius 50 mm standing on end under the 4-stack: the lowest
// layer's planks lie at y = +-46.8 mm, 23.4 mm wide, so each rests on the
// strip of the disc between y = 35.1 and 50 mm, where its own centre (46.8
// mm) lies; every layer above rests across the ends of the one below, its
// load centred on the tower's axis, which is the cylinder's. All stand.
TEST_P(ShapesInMode, ACylinderOnEndCarriesAFourStackOfTenLayers) {
  const double length = 0.1;
  auto world = worldWith(GetParam(), {test::cylinderType("drum", 0.05, length, 0.5, 0.0)});
  ASSERT_TRUE(world->addBrick(at("drum", "drum", Eigen::Vector3d(0, 0, length / 2))).ok);
  for (int i = 0; i < 20; ++i) {
    BrickPlacement p = test::towerBrick(i);
    p.pose.translation().z() += length;
    ASSERT_TRUE(world->addBrick(p).ok) << p.id;
  }
  test::runFor(world.get(), 2.0);
  for (const BrickSnapshot& b : world->snapshot()) {
    EXPECT_NE(b.state, BrickState::kDynamic) << b.id;
    EXPECT_LT((b.pose.translation() - b.placed_pose.translation()).norm(), 1e-6) << b.id;
  }
}

// A plank's rotation that stands it on its end: its length along z, its
// thickness along x.
Eigen::Matrix3d standing() {
  return Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

// Two planks stand on end at x = +-40 mm, their tops 7.8 mm thick along x. A
// roof 120 mm wide across them, its centroid over x = s: with s = 0 it
// rests on both; with s = 38 mm its base no longer reaches the left plank
// (it spans -22 to 98 mm; the plank ends at -36.1 mm), and it balances on
// the right plank's top, 36.1 to 43.9 mm, which holds its centroid; with s
// = 50 mm the centroid lies beyond that top's outer edge: it tips off.
TEST_P(ShapesInMode, ARoofAcrossTwoPlanksStandsAndFallsBeyondItsBalancePoint) {
  const double top = kKaplaLength;
  for (double s : {0.0, 0.038, 0.05}) {
    SCOPED_TRACE("roof centroid at x = " + std::to_string(s));
    auto world = worldWith(GetParam(), {roofType(0.12, 0.03, 0.03, 0.03)});
    for (double x : {-0.04, 0.04})
      ASSERT_TRUE(world
                      ->addBrick(at(x < 0 ? "left" : "right", "kapla",
                                    Eigen::Vector3d(x, 0, top / 2), standing()))
                      .ok);
    ASSERT_TRUE(world->addBrick(at("roof", "roof", Eigen::Vector3d(s, 0, top))).ok);
    const bool stands = s < 0.0439;
    EXPECT_EQ(brick(*world, "roof").state != BrickState::kDynamic, stands);
    test::runFor(world.get(), 1.0);
    const double drop = top - brick(*world, "roof").pose.translation().z();
    if (stands) {
      EXPECT_LT(std::abs(drop), 1e-6);
    } else {
      EXPECT_GT(drop, 0.01);
    }
  }
}

// A plank laid on a lying cylinder touches it along a line: no support
// polygon, and with its centre 30 mm off that line it tips.
TEST_P(ShapesInMode, APlankOffCentreOnALyingCylinderTips) {
  const double r = 0.02;
  auto world = worldWith(GetParam(), {test::cylinderType("log", r, 0.06, 0.1, 0.01)});
  const Eigen::Matrix3d lying =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  ASSERT_TRUE(world->addBrick(at("log", "log", Eigen::Vector3d(0, 0, r), lying)).ok);
  ASSERT_TRUE(
      world->addBrick(at("plank", "kapla", Eigen::Vector3d(0.03, 0, 2 * r + kKaplaThickness / 2)))
          .ok);
  EXPECT_EQ(brick(*world, "plank").state, BrickState::kDynamic);
  test::runFor(world.get(), 1.0);
  // Tipped: its long axis turned well away from level, its far end down.
  const Eigen::Vector3d axis = brick(*world, "plank").pose.linear().col(0);
  EXPECT_GT(std::abs(axis.z()), 0.2);
}

// A column of five drums, each standing on the cap of the one below: every
// cap carries the column above, its weight on the axis. It stands, each
// drum a length above the last.
TEST_P(ShapesInMode, AColumnOfCylindersStands) {
  const double length = 0.06;
  auto world = worldWith(GetParam(), {test::cylinderType("drum", 0.02, length, 0.05, 0.0)});
  ColumnParams params;
  params.count = 5;
  params.type = "drum";
  params.origin = Eigen::Vector2d(0.1, -0.1);
  std::vector<ScheduledBrick> bricks;
  ASSERT_TRUE(generateColumn(params, world->types(), &bricks).ok);
  ASSERT_EQ(bricks.size(), 5u);
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    EXPECT_NEAR(bricks[i].placement.pose.translation().z(), (i + 0.5) * length, 1e-12);
    ASSERT_TRUE(world->addBrick(bricks[i].placement).ok);
  }
  test::runFor(world.get(), 1.0);
  for (const BrickSnapshot& b : world->snapshot()) {
    EXPECT_EQ(b.state, BrickState::kStable) << b.id;
    EXPECT_LT((b.pose.translation() - b.placed_pose.translation()).norm(), 1e-6) << b.id;
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, ShapesInMode, ::testing::ValuesIn(test::modelModes()),
                         test::modeName);

// A cylinder lying on the table, pushed across its axis at v0 = 0.2 m/s:
// it slides, decelerated by mu g, until friction spins it up to rolling at
// 2/3 v0 (a solid cylinder, I = m r^2 / 2), over (v0^2 - (2/3 v0)^2) /
// (2 mu g); then it rolls against Bullet's rolling friction, a torque c N
// with c the cylinder's rolling friction times the table's friction:
// m a (1 + I / (m r^2)) = -c m g / r, a = -(2/3) c g / r, and stops after
// ((2/3) v0)^2 / (2 |a|) = v0^2 r / (3 c g). Without rolling friction it
// rolls on (Bullet even speeds it up a little: docs/design.md, "Brick shapes").
class MotionInMode : public ::testing::TestWithParam<std::string> {};

TEST_P(MotionInMode, ALyingCylinderRollsWhenPushedAndStopsByRollingFriction) {
  const double r = 0.02, v0 = 0.2, m = 0.1, g = 9.81, table_friction = 0.5;
  const double own_rolling = 0.002, c = own_rolling * table_friction;
  const double mu = 0.5;  // pine on the table: both 0.5, combined by their geometric mean
  const double sliding = (v0 * v0 - (2 * v0 / 3) * (2 * v0 / 3)) / (2 * mu * g);  // 2.3 mm
  const double expected = sliding + v0 * v0 * r / (3 * c * g);                    // 29.5 mm
  const Eigen::Matrix3d lying =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (double rolling : {own_rolling, 0.0}) {
    SCOPED_TRACE("rolling friction " + std::to_string(rolling));
    auto world = worldWith(GetParam(), {test::cylinderType("log", r, 0.06, m, rolling)});
    ASSERT_TRUE(world->addBrick(at("log", "log", Eigen::Vector3d(0, 0, r), lying)).ok);
    ASSERT_TRUE(
        world->applyImpulse("log", Eigen::Vector3d(m * v0, 0, 0), Eigen::Vector3d(0, 0, r)).ok);
    test::runFor(world.get(), 0.1);
    // Rolling, not sliding: the spin about the axis matches v / r.
    const BrickSnapshot early = brick(*world, "log");
    EXPECT_NEAR(std::abs(early.angular_velocity.y()) * r, early.linear_velocity.x(),
                0.1 * early.linear_velocity.x());
    test::runFor(world.get(), 2.9);
    const BrickSnapshot late = brick(*world, "log");
    const double travelled = late.pose.translation().x();
    if (rolling > 0.0) {
      EXPECT_LT(late.linear_velocity.norm(), 1e-3);
      EXPECT_NEAR(travelled, expected, 0.1 * expected);
    } else {
      EXPECT_GT(travelled, 10 * expected);
    }
  }
}

// A can thrown at 20 m/s, 20 mm a step, at a plank standing on end 7.8 mm
// thick: faster than the can's own half width (10 mm) a step, so it sweeps
// its prism along each step. Whatever the plank does, the can never sinks
// into it: at every step the solids are apart or touching, and the blow
// takes speed out of the can.
TEST_P(MotionInMode, AFastCanNeverPassesThroughAThinPlank) {
  const double r = 0.01;
  auto world = worldWith(GetParam(), {test::cylinderType("can", r, 0.03, 0.05, 0.0)});
  ASSERT_TRUE(
      world->addBrick(at("wall", "kapla", Eigen::Vector3d(0.0, 0.0, kKaplaLength / 2), standing()))
          .ok);
  BrickPlacement can = at("can", "can", Eigen::Vector3d(-0.08, 0.0, 0.06),
                          Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix());
  can.linear_velocity = Eigen::Vector3d(20.0, 0.0, 0.0);
  ASSERT_TRUE(world->addBrick(can).ok);
  double deepest = 0.0;
  for (int i = 0; i < 50; ++i) {
    world->step();
    const BrickSnapshot a = brick(*world, "can"), b = brick(*world, "wall");
    deepest = std::max(deepest, -separation(PlacedSolid{a.pose, a.solid.get()},
                                            PlacedSolid{b.pose, b.solid.get()}));
  }
  EXPECT_LT(deepest, 1e-3) << "the can sank this deep into the plank [m]";
  // It struck: a can that passed through would keep its 20 m/s.
  EXPECT_LT(brick(*world, "can").linear_velocity.x(), 19.0);
}

INSTANTIATE_TEST_SUITE_P(Modes, MotionInMode, ::testing::ValuesIn(test::allModes()),
                         test::modeName);

}  // namespace
}  // namespace brick_stack_sim
