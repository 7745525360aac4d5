// Every entry point of the world fed with bad input: each call must fail with a
// message that says what was wrong, and leave the world bit-for-bit unchanged.
#include <limits>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::fingerprint;
using test::placement;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// In both modes: with the stability layer the base brick is frozen, so the
/// refusals also cover the frozen bricks' side of every check.
class InvalidInput : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    WorldOptions options;
    options.stability.mode = GetParam();
    world_ = test::makeWorld(options);
    ASSERT_TRUE(world_->addBrick(placement("base", {0, 0, 0.0039})).ok);
    for (int i = 0; i < 20; ++i) world_->step();
    world_->takeEvents();
    before_ = fingerprint(*world_);
    revision_before_ = world_->revision();
  }

  /// The request must be refused, say `expected` in its message, and change nothing.
  void expectRefused(const Status& status, const std::string& expected) {
    EXPECT_FALSE(status.ok);
    EXPECT_NE(status.message.find(expected), std::string::npos)
        << "message '" << status.message << "' does not mention '" << expected << "'";
    EXPECT_TRUE(fingerprint(*world_) == before_) << "a refused request changed the world";
    // A publisher following revision() would otherwise read every moving
    // brick again for nothing.
    EXPECT_EQ(world_->revision(), revision_before_) << "a refused request counted as a change";
    EXPECT_TRUE(world_->takeEvents().empty()) << "a refused request emitted an event";
    EXPECT_EQ(world_->brickCount(), 1u);
  }

  std::unique_ptr<BrickWorld> world_;
  std::string before_;
  std::uint64_t revision_before_ = 0;
};

TEST_P(InvalidInput, NonFinitePositionInEachAxis) {
  for (int axis = 0; axis < 3; ++axis) {
    for (double bad : {kNaN, kInf, -kInf}) {
      Eigen::Vector3d position(0, 0.1, 0.0039);
      position[axis] = bad;
      expectRefused(world_->addBrick(placement("new", position)), "position is not finite");
    }
  }
}

TEST_P(InvalidInput, NonFiniteOrNonRotationOrientation) {
  BrickPlacement p = placement("new", {0, 0.1, 0.0039});
  p.pose.linear()(0, 1) = kNaN;
  expectRefused(world_->addBrick(p), "orientation");
  p = placement("new", {0, 0.1, 0.0039});
  p.pose.linear() *= 1.5;  // scaled: not a rotation
  expectRefused(world_->addBrick(p), "orientation");
  p = placement("new", {0, 0.1, 0.0039});
  p.pose.linear()(2, 2) = -1.0;  // a mirror image
  expectRefused(world_->addBrick(p), "orientation");
}

TEST_P(InvalidInput, NonFiniteOrExcessiveVelocity) {
  for (int axis = 0; axis < 3; ++axis) {
    BrickPlacement p = placement("new", {0, 0.1, 0.0039});
    p.linear_velocity[axis] = kNaN;
    expectRefused(world_->addBrick(p), "velocity is not finite");
    p = placement("new", {0, 0.1, 0.0039});
    p.angular_velocity[axis] = kInf;
    expectRefused(world_->addBrick(p), "velocity is not finite");
  }
  BrickPlacement p = placement("new", {0, 0.1, 0.0039});
  p.linear_velocity.x() = 1e6;
  // Numbers as %g writes them, not "1000000.000000 m/s exceeds the limit of 50.000000".
  expectRefused(world_->addBrick(p), "linear speed 1e+06 m/s, over the limit of 50 m/s");
  p.linear_velocity.x() = 0.0;
  p.angular_velocity.z() = 600.0;
  expectRefused(world_->addBrick(p), "angular speed 600 rad/s, over the limit of 500 rad/s");
}

TEST_P(InvalidInput, UnknownTypeAndBadOrDuplicateId) {
  expectRefused(world_->addBrick(placement("new", {0, 0.1, 0.0039}, 0.0, "granite")),
                "unknown brick type 'granite'");
  expectRefused(world_->addBrick(placement("base", {0, 0.1, 0.0039})), "already in use");
  // The fixed bodies' names, in any case (`supported_by: [floor]`
  // must not be ambiguous).
  for (const char* reserved : {"table", "floor", "world", "Table", "FLOOR", "WoRlD"})
    expectRefused(world_->addBrick(placement(reserved, {0, 0.1, 0.0039})), "is reserved");
  EXPECT_TRUE(world_->checkPlacement(placement("floor_1", {0, 0.1, 0.0039})).ok);
  expectRefused(world_->addBrick(placement("has space", {0, 0.1, 0.0039})), "not valid");
  expectRefused(world_->addBrick(placement("/slash", {0, 0.1, 0.0039})), "not valid");
  expectRefused(world_->removeBrick("ghost"), "no brick with id 'ghost'");
  expectRefused(world_->removeBrick(""), "no brick with id");
}

TEST_P(InvalidInput, AHugeIdIsCutShortInTheMessage) {
  const std::string huge = "b" + std::string(10239, 'x');
  for (const Status& refused : {world_->addBrick(placement(huge, {0, 0.1, 0.0039})),
                                world_->removeBrick(huge), world_->graspBrick(huge)}) {
    EXPECT_FALSE(refused.ok);
    EXPECT_LT(refused.message.size(), 300u) << refused.message.substr(0, 300);
    EXPECT_NE(refused.message.find("(10240 characters)"), std::string::npos)
        << refused.message.substr(0, 300);
  }
}

TEST_P(InvalidInput, PoseInsideAnotherBrickOrUnderTheTable) {
  expectRefused(world_->addBrick(placement("new", {0.01, 0, 0.006})), "overlaps brick 'base'");
  expectRefused(world_->addBrick(placement("new", {0, 0, 0.0039}, M_PI / 2)),
                "overlaps brick 'base'");
  expectRefused(world_->addBrick(placement("new", {0, 0.2, 0.002})), "below the table top");
  expectRefused(world_->addBrick(placement("new", {0, 0.2, -0.5})), "below the table top");
  // Standing on end, a KAPLA plank reaches 58.5 mm down from its centre.
  BrickPlacement upright = placement("new", {0, 0.2, 0.05});
  upright.pose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  expectRefused(world_->addBrick(upright), "below the table top");
}

TEST_P(InvalidInput, FiniteButAbsurdPositionsLieOutsideTheWorldBox) {
  // Before the world box, x = 1e300 missed the floor and fell for ever;
  // z = 1e300 hung in the air. Both, and anything past the default 10 m box, are refused.
  for (const Eigen::Vector3d& far :
       {Eigen::Vector3d(1e300, 0, 0.0039), Eigen::Vector3d(0, -1e300, 0.0039),
        Eigen::Vector3d(0, 0, 1e300), Eigen::Vector3d(10.01, 0, 0.0039),
        Eigen::Vector3d(0, 0, 10.01)}) {
    expectRefused(world_->addBrick(placement("far", far)), "outside the world box");
    PlacementReport report;
    expectRefused(world_->evaluatePlacement(placement("far", far), &report),
                  "outside the world box");
  }
  // The box's edge itself is inside.
  EXPECT_TRUE(world_->checkPlacement(placement("edge", {9.99, 0, 0.5})).ok);
  ASSERT_TRUE(world_->graspBrick("base").ok);
  world_->takeEvents();
  const Status target = world_->setHeldTarget(Eigen::Isometry3d(Eigen::Translation3d(0, 0, 1e300)));
  EXPECT_FALSE(target.ok);
  EXPECT_NE(target.message.find("outside the world box"), std::string::npos) << target.message;
}

TEST_P(InvalidInput, TouchingIsNotOverlapping) {
  // Exactly on top of the base brick, and exactly beside it: both accepted.
  EXPECT_TRUE(world_->checkPlacement(placement("up", {0, 0, 0.0039 + 0.0078})).ok);
  EXPECT_TRUE(world_->checkPlacement(placement("side", {0, 0.0234, 0.0039})).ok);
  EXPECT_TRUE(fingerprint(*world_) == before_);  // checking changes nothing either
}

TEST_P(InvalidInput, NonFiniteImpulse) {
  expectRefused(world_->applyImpulse("base", {kNaN, 0, 0}, {0, 0, 0}), "impulse is not finite");
  expectRefused(world_->applyImpulse("base", {0, 0, 0.001}, {0, kInf, 0}), "point");
  expectRefused(world_->applyImpulse("ghost", {0, 0, 0.001}, {0, 0, 0}), "no brick");
  expectRefused(world_->applyImpulse("base", {1e3, 0, 0}, {0, 0, 0.0039}),
                "m/s, over the limit of 50 m/s");
  // 0.5 N s at the end of the brick about z: 0.5 * L/2 / I_zz = 2000 rad/s.
  expectRefused(world_->applyImpulse("base", {0, 0.5, 0}, {0.0585, 0, 0.0039}), "spinning");
  expectRefused(world_->applyImpulse("base", {0, 0, 0.001}, {1.0, 0, 0.0039}), "outside brick");
}

TEST_P(InvalidInput, HeldBrickRequestsOutOfTurn) {
  expectRefused(world_->graspBrick("ghost"), "no brick with id 'ghost'");
  expectRefused(world_->releaseBrick("base", {0, 0, 0}, {0, 0, 0}), "is not held");
  expectRefused(world_->setHeldTarget(Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.1))),
                "no brick is held");
}

INSTANTIATE_TEST_SUITE_P(Modes, InvalidInput, ::testing::ValuesIn(availableStabilityModes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(InvalidOptions, EveryBadSettingIsNamed) {
  struct Case {
    const char* name;
    void (*spoil)(WorldOptions*);
  };
  const Case cases[] = {
      {"time_step", [](WorldOptions* o) { o->time_step = 0.0; }},
      {"time_step", [](WorldOptions* o) { o->time_step = kNaN; }},
      {"time_step", [](WorldOptions* o) { o->time_step = -0.001; }},
      {"solver_iterations", [](WorldOptions* o) { o->solver_iterations = 0; }},
      {"gravity", [](WorldOptions* o) { o->gravity = kInf; }},
      {"sleeping/linear_threshold", [](WorldOptions* o) { o->sleeping.linear_threshold = -1; }},
      {"sleeping/time", [](WorldOptions* o) { o->sleeping.time = 0; }},
      {"erp", [](WorldOptions* o) { o->erp = 2.0; }},
      {"table/size", [](WorldOptions* o) { o->table.size.y() = 0.0; }},
      {"table/height", [](WorldOptions* o) { o->table.height = kNaN; }},
      {"table/friction", [](WorldOptions* o) { o->table.friction = -0.1; }},
      {"bounds/horizontal", [](WorldOptions* o) { o->bounds.horizontal = kNaN; }},
      {"bounds/horizontal", [](WorldOptions* o) { o->bounds.horizontal = 1e5; }},
      {"bounds/horizontal = 0.5: must reach the table's edges (table/size / 2 = 0.6 m)",
       [](WorldOptions* o) { o->bounds.horizontal = 0.5; }},  // the table is 1.2 m long
      {"bounds/height", [](WorldOptions* o) { o->bounds.height = 0.0; }},
      {"overlap_tolerance", [](WorldOptions* o) { o->overlap_tolerance = kNaN; }},
      {"stability/mode = 'magic'", [](WorldOptions* o) { o->stability.mode = "magic"; }},
      {"stability/rest_time", [](WorldOptions* o) { o->stability.rest_time = -1.0; }},
  };
  for (const Case& c : cases) {
    WorldOptions options;
    c.spoil(&options);
    std::unique_ptr<BrickWorld> world;
    const Status status = BrickWorld::create(options, test::packageTypes(), &world);
    EXPECT_FALSE(status.ok) << c.name;
    EXPECT_EQ(world, nullptr);
    EXPECT_NE(status.message.find(c.name), std::string::npos) << status.message;
  }
  std::unique_ptr<BrickWorld> world;
  EXPECT_FALSE(BrickWorld::create(WorldOptions(), BrickTypeLibrary(), &world).ok);
}

}  // namespace
}  // namespace brick_stack_sim
