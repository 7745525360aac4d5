// Numerical stress that is quick enough for every test run; the long ones
// (133 floors, 2000 bricks, a million steps) are in scripts/run_stress.sh.
#include <cmath>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/types/stability_modes.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;
using test::placement;
using test::runFor;

void expectFiniteAndComplete(const BrickWorld& world, std::size_t bricks) {
  const std::vector<BrickSnapshot> all = world.snapshot();
  EXPECT_EQ(all.size(), bricks);
  for (const BrickSnapshot& b : all) {
    EXPECT_TRUE(b.pose.matrix().allFinite()) << b.id;
    EXPECT_TRUE(b.linear_velocity.allFinite() && b.angular_velocity.allFinite()) << b.id;
    EXPECT_TRUE(b.com_above.allFinite() && std::isfinite(b.margin)) << b.id;
  }
  EXPECT_EQ(world.cost().nonfinite, 0u);
  const Status consistent = world.checkInvariants();
  EXPECT_TRUE(consistent.ok) << consistent.message;
}

class StressByMode : public ::testing::TestWithParam<std::string> {
 protected:
  WorldOptions options() const {
    WorldOptions o;
    o.stability.mode = GetParam();
    return o;
  }
};

TEST_P(StressByMode, HeavyBrickOnALightOneRestsOnIt) {
  BrickTypeLibrary types = test::packageTypes();
  BrickType heavy = *types.find("kapla");
  heavy.name = "heavy_kapla";
  heavy.mass *= 100.0;
  heavy.inertia *= 100.0;
  ASSERT_TRUE(types.add(heavy).ok);
  std::unique_ptr<BrickWorld> world;
  ASSERT_TRUE(BrickWorld::create(options(), types, &world).ok);
  ASSERT_TRUE(world->addBrick(placement("light", {0, 0, kKaplaThickness / 2})).ok);
  ASSERT_TRUE(world
                  ->addBrick(placement("heavy", {0, 0, 1.5 * kKaplaThickness + 0.002}, M_PI / 2,
                                       "heavy_kapla"))
                  .ok);
  runFor(world.get(), 3.0);
  expectFiniteAndComplete(*world, 2);
  BrickSnapshot light, top;
  ASSERT_TRUE(world->find("light", &light));
  ASSERT_TRUE(world->find("heavy", &top));
  // 1.19 kg on 11.9 g: the light brick must neither be crushed into the table
  // nor let the heavy one sink into it by more than a fraction of a millimetre.
  EXPECT_NEAR(light.pose.translation().z(), kKaplaThickness / 2, 3e-4);
  EXPECT_NEAR(top.pose.translation().z(), 1.5 * kKaplaThickness, 3e-4);
  EXPECT_GT(separation({light.pose, 0.5 * light.size}, {top.pose, 0.5 * top.size}), -3e-4);
}

TEST_P(StressByMode, QuarterThicknessInitialOverlapIsPushedApartGently) {
  WorldOptions o = options();
  o.overlap_tolerance = 0.003;  // admit the overlap on purpose
  auto world = test::makeWorld(o);
  const double overlap = 0.25 * kKaplaThickness;
  ASSERT_TRUE(world->addBrick(placement("base", {0, 0, kKaplaThickness / 2})).ok);
  ASSERT_TRUE(world->addBrick(placement("sunk", {0, 0, 1.5 * kKaplaThickness - overlap}, 0.3)).ok);
  runFor(world.get(), 2.0);
  expectFiniteAndComplete(*world, 2);
  EXPECT_EQ(world->cost().blowups, 0u);
  BrickSnapshot base, sunk;
  ASSERT_TRUE(world->find("base", &base));
  ASSERT_TRUE(world->find("sunk", &sunk));
  // Split impulse moves them apart without launching the upper brick.
  EXPECT_GT(separation({base.pose, 0.5 * base.size}, {sunk.pose, 0.5 * sunk.size}), -2e-4);
  EXPECT_LT(sunk.pose.translation().z(), 1.5 * kKaplaThickness + 2e-3);
  EXPECT_FALSE(sunk.fell_off);
}

TEST_P(StressByMode, TimeStepsUpToBlowUpNeverLeakNaN) {
  Scene scene;
  ASSERT_TRUE(loadScene("tower10", {test::dataPath("scenes")}, test::packageTypes(), &scene).ok);
  for (double time_step : {1.0 / 1000, 1.0 / 240, 1.0 / 60, 1.0 / 30, 1.0 / 15}) {
    RunOptions run;
    run.world = options();
    run.world.sleeping.enabled = false;
    run.world.time_step = time_step;
    run.world.solver_iterations = 5;
    run.duration = 5.0;
    RunReport report;
    ASSERT_TRUE(runScene(scene, test::packageTypes(), run, &report).ok);
    EXPECT_EQ(report.bricks.size(), 20u) << time_step;
    EXPECT_EQ(report.cost.nonfinite, 0u) << time_step;
    for (const BrickOutcome& b : report.bricks)
      EXPECT_TRUE(b.brick.pose.matrix().allFinite()) << time_step << " " << b.brick.id;
    // A NaN would be written as null; the fall times are null by design
    // when nothing fell.
    std::string json = toJson(report);
    const std::string by_design[] = {"\"fell_at\": null", "\"first_fall_t\": null"};
    for (const std::string& none : by_design)
      for (std::size_t at; (at = json.find(none)) != std::string::npos;)
        json.erase(at, none.size());
    EXPECT_EQ(json.find("null"), std::string::npos) << time_step;
  }
}

TEST_P(StressByMode, SamePileTwiceGivesBitIdenticalReports) {
  Scene scene;
  ASSERT_TRUE(parseScene("generator: {name: pile, bricks: 40, columns: 4, rows: 2, seed: 3}\n",
                         "pile40", test::packageTypes(), &scene)
                  .ok);
  RunOptions run;
  run.world = options();
  run.duration = 1.5;
  RunReport first, second;
  ASSERT_TRUE(runScene(scene, test::packageTypes(), run, &first).ok);
  ASSERT_TRUE(runScene(scene, test::packageTypes(), run, &second).ok);
  ASSERT_EQ(first.bricks.size(), second.bricks.size());
  for (std::size_t i = 0; i < first.bricks.size(); ++i) {
    const Eigen::Matrix4d& a = first.bricks[i].brick.pose.matrix();
    const Eigen::Matrix4d& b = second.bricks[i].brick.pose.matrix();
    EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * 16), 0) << first.bricks[i].brick.id;
  }
  EXPECT_EQ(first.events.size(), second.events.size());
}

INSTANTIATE_TEST_SUITE_P(Modes, StressByMode, ::testing::ValuesIn(availableStabilityModes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace brick_stack_sim
