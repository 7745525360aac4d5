// The stack stability layer (mode com) against statics with exact answers
// (docs/testing.md, "Ground truth"). Expected values come from hand statics in each test,
// never from the model's own output.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/scene/generators.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaMass;
using test::kKaplaThickness;
using test::kKaplaWidth;
using test::placement;
using test::runFor;

double displacement(const BrickSnapshot& b) {
  return (b.pose.translation() - b.placed_pose.translation()).norm();
}

std::set<std::string> woken(const std::vector<SimEvent>& events) {
  std::set<std::string> ids;
  for (const SimEvent& e : events)
    if (e.kind == SimEventKind::kWoken) ids.insert(e.brick_id);
  return ids;
}

RunReport runScene(const std::string& yaml, double duration) {
  Scene scene;
  const BrickTypeLibrary types = test::packageTypes();
  const Status parsed = parseScene(yaml, "test", types, &scene);
  EXPECT_TRUE(parsed.ok) << parsed.message;
  RunOptions options;
  options.world = test::optionsFor("com");
  options.duration = duration;
  RunReport report;
  const Status ran = brick_stack_sim::runScene(scene, types, options, &report);
  EXPECT_TRUE(ran.ok) << ran.message;
  return report;
}

/// Places a two-brick-per-layer tower (the `tower` generator) at once.
void placeTower(BrickWorld* world, int layers) {
  std::vector<ScheduledBrick> tower;
  TowerParams params;
  params.layers = layers;
  ASSERT_TRUE(generateTower(params, world->types(), &tower).ok);
  for (const ScheduledBrick& b : tower) ASSERT_TRUE(world->addBrick(b.placement).ok);
}

// --- a brick over the table edge ------------------------------------------

/// A plank along x over the table's +x edge with its centre `overhang` [m]
/// past it: statics says it stays iff its centre is over the table.
BrickSnapshot plankOverEdgeAfter(double centre_past_edge, double seconds) {
  WorldOptions options = test::optionsFor("com");
  options.table.size = Eigen::Vector2d(0.4, 0.4);
  auto world = test::makeWorld(options);
  EXPECT_TRUE(
      world->addBrick(placement("plank", {0.2 + centre_past_edge, 0, kKaplaThickness / 2})).ok);
  runFor(world.get(), seconds);
  BrickSnapshot plank;
  EXPECT_TRUE(world->find("plank", &plank));
  return plank;
}

TEST(ComStability, PlankWithItsCentreJustOverTheTableStays) {
  for (double inside : {0.002, 0.005}) {
    const BrickSnapshot plank = plankOverEdgeAfter(-inside, 3.0);
    EXPECT_EQ(plank.state, BrickState::kStable) << inside;
    EXPECT_LT(displacement(plank), 1e-5) << inside;
    EXPECT_NEAR(plank.margin, inside, 1e-6) << "the margin is the distance to the edge";
    EXPECT_EQ(plank.supported_by, std::vector<std::string>{"table"});
  }
}

TEST(ComStability, PlankWithItsCentreJustPastTheEdgeFalls) {
  for (double outside : {0.002, 0.005}) {
    const BrickSnapshot plank = plankOverEdgeAfter(outside, 3.0);
    EXPECT_TRUE(plank.fell_off) << outside;
    // It may have come to rest on the floor since, and joined a stack there.
    if (plank.state == BrickState::kStable) {
      EXPECT_EQ(plank.supported_by, std::vector<std::string>{"floor"}) << outside;
    }
  }
}

// --- harmonic stacks -------------------------------------------------------

std::string harmonicScene(int bricks, double factor) {
  return "table: {size: [0.6, 0.6]}\ngenerator: {name: harmonic, bricks: " +
         std::to_string(bricks) + ", factor: " + std::to_string(factor) + "}\n";
}

TEST(ComStability, HarmonicStacksBelowTheLimitStandStill) {
  for (int bricks : {4, 8}) {
    const RunReport report = runScene(harmonicScene(bricks, 0.95), 20.0);
    ASSERT_EQ(report.bricks.size(), static_cast<std::size_t>(bricks));
    for (const BrickOutcome& b : report.bricks) {
      EXPECT_EQ(b.brick.state, BrickState::kStable) << bricks << " " << b.brick.id;
      EXPECT_LT(b.displacement, 1e-5) << bricks << " " << b.brick.id;
    }
  }
}

TEST(ComStability, HarmonicStacksBeyondTheLimitFall) {
  for (int bricks : {4, 8}) {
    const RunReport report = runScene(harmonicScene(bricks, 1.05), 20.0);
    // The top brick's COM is 5 % of its own overhang past the edge below it.
    const BrickOutcome& top = report.bricks.back();
    EXPECT_GT(top.displacement, 0.05) << bricks;
    EXPECT_TRUE(top.brick.fell_off) << bricks;
  }
}

// --- slant towers ------------------------------------------------------------

/// Statics: bricks j = 1..n at x = (j - 1) d. Layer n breaks the tower when for
/// some k the COM of bricks k+1..n passes the right end of brick k.
int staticsCollapseLayer(double offset, double length) {
  for (int n = 2; n < 1000; ++n) {
    for (int k = 1; k < n; ++k) {
      double com = 0.0;
      for (int j = k + 1; j <= n; ++j) com += (j - 1) * offset;
      com /= (n - k);
      if (com > (k - 1) * offset + length / 2) return n;
    }
  }
  return -1;
}

TEST(ComStability, SlantTowerCollapsesExactlyAtTheStaticsLayer) {
  for (double offset : {0.011, 0.014, 0.025}) {
    const int collapse = staticsCollapseLayer(offset, kKaplaLength);
    ASSERT_GT(collapse, 2);
    // Built one brick per second; look just before and after the deciding brick.
    std::ostringstream yaml;
    yaml << "generator: {name: slant_tower, layers: " << collapse << ", offset: " << offset
         << ", interval: 1.0}\n";
    const RunReport before =
        runScene(yaml.str(), collapse - 1 - 0.01);  // last brick not yet placed
    ASSERT_EQ(before.bricks.size(), static_cast<std::size_t>(collapse - 1));
    for (const BrickOutcome& b : before.bricks) {
      EXPECT_EQ(b.brick.state, BrickState::kStable) << offset << " " << b.brick.id;
      EXPECT_LT(b.displacement, 1e-5) << offset << " " << b.brick.id;
    }
    const RunReport after = runScene(yaml.str(), collapse + 3.0);
    ASSERT_EQ(after.bricks.size(), static_cast<std::size_t>(collapse));
    // The bottom brick is not in the collapse: it is not woken when the
    // tower fails. Then the falling bricks may shove it (plain Bullet at
    // 1/4000 s and 100 iterations moves it some millimetres too), but it
    // stays on the table and flat. Every brick above it goes.
    EXPECT_EQ(after.cost.wake_cycles, 0u) << offset;
    const double collapse_time = collapse - 1.0;  // the deciding brick's placement
    for (const SimEvent& e : after.events) {
      if (e.kind == SimEventKind::kWoken && e.time < collapse_time + 0.1) {
        EXPECT_NE(e.brick_id, "b0") << offset << " at " << e.time << ": " << e.reason;
      }
    }
    EXPECT_LT(after.bricks[0].displacement, 0.03) << offset;
    EXPECT_LT(after.bricks[0].rotation, 0.05) << offset;
    for (std::size_t i = 1; i < after.bricks.size(); ++i) {
      const BrickOutcome& b = after.bricks[i];
      EXPECT_TRUE(b.displacement > 0.005 || b.rotation > 0.1)
          << offset << " layer " << i + 1 << ": moved " << b.displacement << " m, turned "
          << b.rotation << " rad";
    }
    // What woke first is the second brick, whose COM-above left brick 1.
    auto first_woken =
        std::find_if(after.events.begin(), after.events.end(),
                     [](const SimEvent& e) { return e.kind == SimEventKind::kWoken; });
    ASSERT_NE(first_woken, after.events.end()) << offset;
    EXPECT_EQ(first_woken->brick_id, "b1") << offset;
    EXPECT_NE(first_woken->reason.find("COM-above left its support"), std::string::npos)
        << first_woken->reason;
  }
}

// --- the thesis's headline --------------------------------------------------

TEST(ComStability, TwentyFiveLayerTowerBuiltBrickByBrickStandsStill) {
  Scene scene;
  const BrickTypeLibrary types = test::packageTypes();
  ASSERT_TRUE(loadScene("tower25_built", {test::dataPath("scenes")}, types, &scene).ok);
  RunOptions options;
  options.world = test::optionsFor("com");
  options.duration = 49.0 + 30.0;  // the last brick is placed at 49 s
  RunReport report;
  ASSERT_TRUE(brick_stack_sim::runScene(scene, types, options, &report).ok);
  ASSERT_EQ(report.bricks.size(), 50u);
  for (const BrickOutcome& b : report.bricks) {
    EXPECT_EQ(b.brick.state, BrickState::kStable) << b.brick.id;
    EXPECT_LT(b.displacement, 1e-5) << b.brick.id;
  }
  EXPECT_TRUE(woken(report.events).empty());
  EXPECT_EQ(report.cost.nonfinite, 0u);
}

// --- loads act where they are transmitted ------------------------------------

TEST(ComStability, FourStackLowerBricksCarryTheCrossingLoadOverThemselves) {
  // Two planks on the table at y = -s and +s, two across them at x = -s, +s.
  // Each upper plank hands each lower one half its weight at the crossing
  // (x = +-s, y of the lower plank): a lower plank's COM-above stays over its
  // own centre line (y = its y) with twice its mass. The thesis's equation 10
  // would put it at y = -s/2, outside its 23.4 mm wide footprint.
  auto world = test::makeWorld(test::optionsFor("com"));
  const double s = (kKaplaLength - kKaplaWidth) / 2, h = kKaplaThickness;
  ASSERT_TRUE(world->addBrick(placement("low_a", {0, -s, h / 2})).ok);
  ASSERT_TRUE(world->addBrick(placement("low_b", {0, s, h / 2})).ok);
  ASSERT_TRUE(world->addBrick(placement("up_a", {-s, 0, 1.5 * h}, M_PI / 2)).ok);
  ASSERT_TRUE(world->addBrick(placement("up_b", {s, 0, 1.5 * h}, M_PI / 2)).ok);
  runFor(world.get(), 2.0);
  BrickSnapshot low;
  ASSERT_TRUE(world->find("low_a", &low));
  EXPECT_EQ(low.state, BrickState::kStable);
  // Bricks settle by micrometres before they freeze: shares within 1e-8 kg.
  EXPECT_NEAR(low.mass_above, 2 * kKaplaMass, 1e-8);
  EXPECT_NEAR(low.com_above.x(), 0.0, 1e-6);
  EXPECT_NEAR(low.com_above.y(), -s, 1e-6);
  EXPECT_NEAR(low.margin, kKaplaWidth / 2, 1e-6);
  for (const BrickSnapshot& b : world->snapshot()) EXPECT_LT(displacement(b), 1e-5) << b.id;
  EXPECT_TRUE(woken(world->takeEvents()).empty());
}

TEST(ComStability, BridgeLoadedOffCentrePassesLeverRuleShares) {
  // Two towers of two cubes at x = -a and +a; a KAPLA bridge across them,
  // centred; a half plank on the bridge at (x_h, y_h).
  auto world = test::makeWorld(test::optionsFor("com"));
  const double cube = 0.0234, a = 0.04, h = kKaplaThickness;
  const double x_h = 0.03, y_h = 0.005;
  for (double x : {-a, a}) {
    const std::string side = x < 0 ? "left" : "right";
    ASSERT_TRUE(world->addBrick(placement(side + "_0", {x, 0, cube / 2}, 0, "cube")).ok);
    ASSERT_TRUE(world->addBrick(placement(side + "_1", {x, 0, 1.5 * cube}, 0, "cube")).ok);
  }
  ASSERT_TRUE(world->addBrick(placement("bridge", {0, 0, 2 * cube + h / 2})).ok);
  ASSERT_TRUE(
      world->addBrick(placement("load", {x_h, y_h, 2 * cube + 1.5 * h}, 0, "half_kapla")).ok);
  runFor(world.get(), 2.0);

  // Hand statics. The bridge's COM-above: the bridge and the load over it.
  const BrickType& cube_type = *world->types().find("cube");
  const double m_cube = cube_type.mass, m_bridge = kKaplaMass;
  const double m_load = world->types().find("half_kapla")->mass;
  const double m_total = m_bridge + m_load;
  const double c_x = m_load * x_h / m_total, c_y = m_load * y_h / m_total;
  // Lever rule between the patch centres (-a, 0) and (a, 0): the right tower
  // takes t = (c_x + a) / 2a; both act at y = c_y to balance the moment about x.
  const double t = (c_x + a) / (2 * a);
  const double right_share = m_total * t, left_share = m_total * (1 - t);

  BrickSnapshot right_top, left_top, right_bottom;
  ASSERT_TRUE(world->find("right_1", &right_top));
  ASSERT_TRUE(world->find("left_1", &left_top));
  ASSERT_TRUE(world->find("right_0", &right_bottom));
  EXPECT_EQ(right_top.state, BrickState::kStable);
  // Bricks settle by micrometres before they freeze, which moves the shares
  // by about 1e-7 kg; an equal split would be off by 1.5e-3 kg.
  EXPECT_NEAR(right_top.mass_above, m_cube + right_share, 1e-6);
  EXPECT_NEAR(left_top.mass_above, m_cube + left_share, 1e-6);
  // The share acts at (+a, c_y): the cube's COM-above moves across by
  // share * c_y / (m_cube + share) and not at all along x. Equation 10 taken
  // literally would pull it 21 mm towards the bridge's centre.
  EXPECT_NEAR(right_top.com_above.x(), a, 1e-6);
  EXPECT_NEAR(left_top.com_above.x(), -a, 1e-6);
  EXPECT_NEAR(right_top.com_above.y(), right_share * c_y / (m_cube + right_share), 1e-5);
  EXPECT_NEAR(left_top.com_above.y(), left_share * c_y / (m_cube + left_share), 1e-5);
  // Down the tower, the bottom cube carries the top cube and its share.
  EXPECT_NEAR(right_bottom.mass_above, 2 * m_cube + right_share, 1e-6);
  for (const BrickSnapshot& b : world->snapshot()) EXPECT_LT(displacement(b), 1e-5) << b.id;
}

// --- wake-up ------------------------------------------------------------------

TEST(ComStability, RemovingASupporterWakesExactlyTheBricksAboveIt) {
  auto world = test::makeWorld(test::optionsFor("com"));
  placeTower(world.get(), 6);
  runFor(world.get(), 1.0);
  for (const BrickSnapshot& b : world->snapshot()) ASSERT_EQ(b.state, BrickState::kStable) << b.id;
  world->takeEvents();

  // Removing the top brick disturbs nothing.
  ASSERT_TRUE(world->removeBrick("b11").ok);
  EXPECT_TRUE(woken(world->takeEvents()).empty());
  // b2 (layer 2) carries both bricks of layer 3, which carry everything above.
  ASSERT_TRUE(world->removeBrick("b2").ok);
  const std::set<std::string> expected{"b4", "b5", "b6", "b7", "b8", "b9", "b10"};
  EXPECT_EQ(woken(world->takeEvents()), expected);
  for (const BrickSnapshot& b : world->snapshot()) {
    const bool above = expected.count(b.id) > 0;
    EXPECT_EQ(b.state, above ? BrickState::kDynamic : BrickState::kStable) << b.id;
  }
}

TEST(ComStability, NothingAwakeMeansNoBulletStep) {
  auto world = test::makeWorld(test::optionsFor("com"));
  ASSERT_TRUE(world->addBrick(placement("a", {0, 0, kKaplaThickness / 2})).ok);
  runFor(world.get(), 0.5);
  BrickSnapshot a;
  ASSERT_TRUE(world->find("a", &a));
  ASSERT_EQ(a.state, BrickState::kStable);
  const CostCounters before = world->cost();
  runFor(world.get(), 1.0);
  EXPECT_EQ(world->cost().bullet_steps, before.bullet_steps);
  EXPECT_EQ(world->cost().stability_updates, before.stability_updates);
  EXPECT_EQ(world->cost().steps, before.steps + 1000);
}

TEST(ComStability, BrickDroppedOntoAFrozenOneAtLongStepsLandsOnIt) {
  // At 1/100 s the dropped brick falls 2 mm in its second step: the frozen
  // brick under it (out of Bullet's world while nothing moved near it) must
  // be back in Bullet by then. (From 1/30 s on, plain Bullet itself lets a
  // brick sink through another: no mode can do better there.)
  WorldOptions options = test::optionsFor("com");
  options.time_step = 1.0 / 100;
  auto world = test::makeWorld(options);
  ASSERT_TRUE(world->addBrick(placement("low", {0, 0, kKaplaThickness / 2})).ok);
  runFor(world.get(), 1.0);
  ASSERT_TRUE(world->addBrick(placement("high", {0, 0, 1.5 * kKaplaThickness + 0.002}, 0.3)).ok);
  runFor(world.get(), 2.0);
  BrickSnapshot low, high;
  ASSERT_TRUE(world->find("low", &low));
  ASSERT_TRUE(world->find("high", &high));
  EXPECT_EQ(low.state, BrickState::kStable);
  EXPECT_LT(displacement(low), 1e-9);
  // On top of it, within the millimetre a 1/100 s step lets any brick sink.
  EXPECT_NEAR(high.pose.translation().z(), 1.5 * kKaplaThickness, 1e-3);
}

TEST(ComStability, FastBrickKnocksAFrozenTowerInsteadOfPassingThrough) {
  // Thrown at 8 m/s from 2 cm beside a frozen 4-layer tower, at layer 1: the
  // blow (95 mJ in the struck brick) tips it with its load. The thrown brick
  // must hand its momentum to the tower, not pass through it as through a
  // collider Bullet never saw, nor bounce off it as off a wall.
  auto world = test::makeWorld(test::optionsFor("com"));
  placeTower(world.get(), 4);
  for (const BrickSnapshot& b : world->snapshot()) ASSERT_EQ(b.state, BrickState::kStable);
  const double tower_face = -kKaplaLength / 2;  // the tower spans x in [-L/2, L/2]
  BrickPlacement thrown = placement(
      "thrown", {tower_face - 0.02 - kKaplaLength / 2, 0, 1.5 * kKaplaThickness}, 0.0, "kapla");
  thrown.linear_velocity = Eigen::Vector3d(8.0, 0, 0);
  ASSERT_TRUE(world->addBrick(thrown).ok);
  world->takeEvents();
  runFor(world.get(), 0.01);
  const std::vector<SimEvent> events = world->takeEvents();
  const auto struck = std::find_if(events.begin(), events.end(), [](const SimEvent& e) {
    return e.kind == SimEventKind::kImpact && e.brick_id == "b2";
  });
  ASSERT_NE(struck, events.end()) << "the layer-1 brick facing the throw was not struck";
  EXPECT_NE(struck->reason.find("tips"), std::string::npos) << struck->reason;
  BrickSnapshot hit, flying;
  ASSERT_TRUE(world->find("b2", &hit));
  ASSERT_TRUE(world->find("thrown", &flying));
  // Momentum handed over: the struck brick moves away at metres per second
  // and the thrown brick has lost speed; it stays behind the struck brick.
  EXPECT_GT(hit.linear_velocity.x(), 1.0);
  EXPECT_LT(flying.linear_velocity.x(), 6.0);
  EXPECT_LT(flying.pose.translation().x(), hit.pose.translation().x());
}

TEST(ComStability, PushingAFrozenBrickWakesItAndWhatItCarries) {
  auto world = test::makeWorld(test::optionsFor("com"));
  ASSERT_TRUE(world->addBrick(placement("low", {0, 0, kKaplaThickness / 2})).ok);
  ASSERT_TRUE(world->addBrick(placement("high", {0, 0, 1.5 * kKaplaThickness})).ok);
  runFor(world.get(), 0.5);
  world->takeEvents();
  ASSERT_TRUE(world->applyImpulse("low", {0.0119 * 0.5, 0, 0}, {0, 0, kKaplaThickness / 2}).ok);
  EXPECT_EQ(woken(world->takeEvents()), (std::set<std::string>{"low", "high"}));
  runFor(world.get(), 0.2);
  BrickSnapshot low;
  ASSERT_TRUE(world->find("low", &low));
  EXPECT_GT(low.pose.translation().x(), 0.005);  // it slid
}

}  // namespace
}  // namespace brick_stack_sim
