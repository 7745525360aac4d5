// Loads that bricks the stack does not hold put on frozen bricks: a plank
// tipping off a frozen plank, a harmonic stack whose top cannot stand, a
// held brick pressed onto a frozen cantilever. Each expected answer is the
// statics of rigid blocks, derived in the comments; the stack must fall
// where statics says it cannot stand, and must not move where it can.

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "support/kapla.h"
#include "support/modes.h"
#include "support/world_probe.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaMass;
using test::kKaplaThickness;
using test::kKaplaWidth;
using test::placement;

/// The +x edge of the default table (1.2 m long, centred on the origin) [m].
constexpr double kTableEdge = 0.6;
constexpr double kAlongY = M_PI / 2.0;  ///< Yaw that lays a KAPLA along y.

class LoadsInMode : public ::testing::TestWithParam<std::string> {};

/// The woken events since the last call, by brick.
std::map<std::string, int> wakesOf(BrickWorld* world) {
  std::map<std::string, int> wakes;
  for (const SimEvent& e : world->takeEvents())
    if (e.kind == SimEventKind::kWoken) ++wakes[e.brick_id];
  return wakes;
}

/// Plank P along x over the table's edge with its centre `inside` [m] in
/// from it; at t = 0.5 s plank T along x on P's free end with its centre
/// `past_end` [m] beyond P's end (negative: inside it). Run for 3 s.
std::unique_ptr<BrickWorld> plankOnCantilever(const std::string& mode, double inside,
                                              double past_end) {
  auto world = test::worldWithFriction(mode, 0.5);
  const double p = kTableEdge - inside;
  EXPECT_TRUE(world->addBrick(placement("P", {p, 0.0, 0.5 * kKaplaThickness})).ok);
  test::runFor(world.get(), 0.5);
  EXPECT_EQ(test::snapshotOf(*world, "P").state, BrickState::kStable);
  EXPECT_TRUE(world
                  ->addBrick(placement(
                      "T", {p + 0.5 * kKaplaLength + past_end, 0.0, 1.5 * kKaplaThickness}))
                  .ok);
  return world;
}

TEST_P(LoadsInMode, APlankTippingOffACantileverTipsItWhenTheirJointComIsPastTheEdge) {
  // P's centre 3 mm inside the edge, T's 1 mm past P's end: T cannot rest on
  // P (its COM is past P's end) and tips about that end. P bears T's weight
  // there, 55.5 mm past the table edge, against its own 3 mm: it tips once
  // T presses with more than 3 / 55.5 = 5.4 % of its weight, and a brick
  // starting to tip about an edge presses with almost all of it (their
  // joint COM is 26.75 mm past the edge). Both go.
  auto world = plankOnCantilever(GetParam(), 0.003, 0.001);
  world->takeEvents();
  test::runFor(world.get(), 3.0);
  const std::map<std::string, int> wakes = wakesOf(world.get());
  EXPECT_EQ(wakes.count("P"), 1u) << "P must leave the stack under T's load";
  for (const char* id : {"P", "T"}) EXPECT_TRUE(test::snapshotOf(*world, id).fell_off) << id;
  EXPECT_EQ(world->cost().wake_cycles, 0u);
}

TEST_P(LoadsInMode, APlankRestingOnACantileverTipsItAsOne) {
  // T's centre 0.5 mm inside P's end: T rests on P (its COM over P) and
  // freezes; their joint COM is still 26 mm past the table edge: both go.
  auto world = plankOnCantilever(GetParam(), 0.003, -0.0005);
  test::runFor(world.get(), 3.0);
  for (const char* id : {"P", "T"}) EXPECT_TRUE(test::snapshotOf(*world, id).fell_off) << id;
}

TEST_P(LoadsInMode, APlankTippingOffAStableCantileverGoesAlone) {
  // P's centre 40 mm inside the edge: T's whole weight at P's end, 18.5 mm
  // past the edge, is less than P's own 40 mm of lever. T tips off alone.
  auto world = plankOnCantilever(GetParam(), 0.040, 0.001);
  world->takeEvents();
  test::runFor(world.get(), 3.0);
  const std::map<std::string, int> wakes = wakesOf(world.get());
  EXPECT_EQ(wakes.count("P"), 0u);
  EXPECT_EQ(test::snapshotOf(*world, "P").state, BrickState::kStable);
  EXPECT_EQ(test::displacement(*world, "P"), 0.0);
  EXPECT_TRUE(test::snapshotOf(*world, "T").fell_off);
}

/// Runs a harmonic stack of `bricks` KAPLAs at `factor` of the critical
/// overhangs over the table's +x edge, placed `interval` [s] apart (0: at
/// once), for `duration` [s].
RunReport runHarmonic(const std::string& mode, int bricks, double factor, double interval,
                      double duration) {
  std::ostringstream yaml;
  yaml << "generator: {name: harmonic, bricks: " << bricks << ", factor: " << factor
       << ", interval: " << interval << "}\n";
  Scene scene;
  const BrickTypeLibrary types = test::packageTypes();
  const Status parsed = parseScene(yaml.str(), "harmonic", types, &scene);
  EXPECT_TRUE(parsed.ok) << parsed.message;
  RunOptions run;
  run.world = test::optionsFor(mode);
  run.duration = duration;
  RunReport report;
  const Status ran = runScene(scene, types, run, &report);
  EXPECT_TRUE(ran.ok) << ran.message;
  return report;
}

TEST_P(LoadsInMode, AHarmonicStackPastItsCriticalOverhangsFallsAsAWhole) {
  // Brick i from the top overhangs the one below by f L / (2 i). For f > 1
  // the COM of every sub-stack lies past the edge of the brick (or table)
  // under it: no sub-stack has an equilibrium, and the collapse mechanism
  // is the whole stack. The top brick cannot even rest on the one below
  // (f L / 2 > L / 2); once its load is seen, every brick is woken at once.
  // Then every joint starts to open at once, each sub-stack's COM
  // (f - 1) L / 2 = 1.75 mm past its edge. The upper bricks, with the least
  // inertia over their edges, turn fastest and fall; once they are gone
  // what is left is within its critical overhangs and stands, so how far
  // the bottom brick moves first (tens of micrometres to millimetres) is
  // the dynamics'. Every brick moves (one left frozen would not move at
  // all), and the upper half falls.
  for (int bricks : {8, 12}) {
    for (double interval : {0.0, 0.25}) {
      SCOPED_TRACE(std::to_string(bricks) + " bricks, placed " + std::to_string(interval) +
                   " s apart");
      const RunReport report =
          runHarmonic(GetParam(), bricks, 1.03, interval, interval * bricks + 3.0);
      ASSERT_EQ(report.bricks.size(), static_cast<std::size_t>(bricks));
      std::map<std::string, double> first_wake;
      for (const SimEvent& e : report.events)
        if (e.kind == SimEventKind::kWoken && !first_wake.count(e.brick_id))
          first_wake[e.brick_id] = e.time;
      const std::string top = report.bricks.back().brick.id;
      int fell = 0;
      for (const BrickOutcome& b : report.bricks) {
        if (b.brick.id != top) {
          ASSERT_TRUE(first_wake.count(b.brick.id)) << b.brick.id << " was never woken";
          EXPECT_EQ(first_wake[b.brick.id], first_wake[report.bricks.front().brick.id])
              << b.brick.id << " woke apart from the rest of the mechanism";
        }
        EXPECT_GT(b.displacement, 2e-5) << b.brick.id;
        fell += b.brick.fell_off;
      }
      EXPECT_TRUE(report.bricks.back().brick.fell_off);
      EXPECT_GE(fell, bricks / 2);
      // The collapse wakes each brick once: none is woken again where it
      // had refrozen while it is on the table. The heap the fallen bricks
      // make on the floor is another matter, loads of bricks still settling
      // on frozen ones (docs/benchmarks.md, "Piles left to settle"), and
      // whether it churns turns on the last bits of the fall.
      std::map<std::string, double> fell_off_at;
      for (const SimEvent& e : report.events)
        if (e.kind == SimEventKind::kFellOff) fell_off_at.emplace(e.brick_id, e.time);
      for (const SimEvent& e : report.events) {
        if (e.kind != SimEventKind::kWoken ||
            e.reason.find("wake/refreeze cycle") == std::string::npos)
          continue;
        const auto fell_off = fell_off_at.find(e.brick_id);
        EXPECT_TRUE(fell_off != fell_off_at.end() && fell_off->second < e.time)
            << e.brick_id << " at " << e.time << " s: " << e.reason;
      }
    }
  }
}

TEST_P(LoadsInMode, AHarmonicStackWithinItsCriticalOverhangsStandsStill) {
  // f = 0.97: every sub-stack's COM lies inside the brick under it.
  for (int bricks : {8, 12}) {
    for (double interval : {0.0, 0.25}) {
      const RunReport report =
          runHarmonic(GetParam(), bricks, 0.97, interval, interval * bricks + 2.0);
      for (const SimEvent& e : report.events)
        EXPECT_NE(e.kind, SimEventKind::kWoken) << e.brick_id << ": " << e.reason;
      for (const BrickOutcome& b : report.bricks) {
        EXPECT_EQ(b.brick.state, BrickState::kStable) << b.brick.id;
        EXPECT_EQ(b.displacement, 0.0) << b.brick.id;
      }
    }
  }
}

TEST_P(LoadsInMode, AHeldBrickPressedOnACantileverTipsItOnlyPastTheStaticsForce) {
  // P along x over the table edge, its centre c = 10 mm inside. The hand
  // lays H across P's free end (along y, its near face flush with P's end)
  // and is a spring to its target: with the target d below where P stops
  // H, it presses with k d on their patch, whose centre is W / 2 = 11.7 mm
  // inside P's end: a = L / 2 - c - W / 2 = 36.8 mm past the edge. P tips
  // when k d a > m g c: F* = m g c / a = 31.7 mN. 0.8 F* holds, 1.25 F*
  // does not: P leaves the stack and tips as far as the hand, holding its
  // target, lets it; lifted away, the hand lets it fall.
  const double c = 0.010;
  const double a = 0.5 * kKaplaLength - c - 0.5 * kKaplaWidth;
  const double critical = kKaplaMass * 9.81 * c / a;
  for (const double force : {0.8 * critical, 1.25 * critical}) {
    SCOPED_TRACE("pressing with " + std::to_string(force) + " N");
    auto world = test::worldWithFriction(GetParam(), 0.5);
    const double stiffness = world->options().held.stiffness;
    ASSERT_GT(stiffness, 0.0);
    const double p = kTableEdge - c;
    ASSERT_TRUE(world->addBrick(placement("P", {p, 0.0, 0.5 * kKaplaThickness})).ok);
    ASSERT_TRUE(world->addBrick(placement("H", {0.0, 0.0, 0.5 * kKaplaThickness}, kAlongY)).ok);
    test::runFor(world.get(), 0.1);
    ASSERT_TRUE(world->graspBrick("H").ok);
    const Eigen::Vector3d on_end(p + 0.5 * kKaplaLength - 0.5 * kKaplaWidth, 0.0,
                                 1.5 * kKaplaThickness);
    auto pose = [](const Eigen::Vector3d& at) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = at;
      pose.linear() = Eigen::AngleAxisd(kAlongY, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      return pose;
    };
    ASSERT_TRUE(world->setHeldTarget(pose(on_end + Eigen::Vector3d(0.0, 0.0, 0.01))).ok);
    test::runFor(world.get(), 2.0);
    world->takeEvents();
    ASSERT_TRUE(
        world->setHeldTarget(pose(on_end - Eigen::Vector3d(0.0, 0.0, force / stiffness))).ok);
    test::runFor(world.get(), 1.0);
    const std::map<std::string, int> wakes = wakesOf(world.get());
    ASSERT_TRUE(world->setHeldTarget(pose(on_end + Eigen::Vector3d(0.0, 0.0, 0.05))).ok);
    test::runFor(world.get(), 1.0);
    if (force < critical) {
      EXPECT_EQ(wakes.count("P"), 0u);
      EXPECT_EQ(test::snapshotOf(*world, "P").state, BrickState::kStable);
      EXPECT_EQ(test::displacement(*world, "P"), 0.0);
    } else {
      EXPECT_EQ(wakes.count("P"), 1u);
      EXPECT_TRUE(test::snapshotOf(*world, "P").fell_off);
    }
  }
}

TEST_P(LoadsInMode, ABrickSlidAcrossATowerTopOrSetDownOnItWakesNothing) {
  // A KAPLA sliding across the top layer of a frozen 6-layer tower pulls
  // the top plank it rubs on sideways with mu m g, against friction of
  // mu (m_top + m) g under it; one set down on the top presses with its
  // weight, inside the top's support. Statics holds throughout: nothing of
  // the tower wakes or moves.
  for (const bool sliding : {true, false}) {
    SCOPED_TRACE(sliding ? "slid across" : "set down");
    auto world = test::worldWithFriction(GetParam(), 0.5);
    for (int i = 0; i < 12; ++i) ASSERT_TRUE(world->addBrick(test::towerBrick(i)).ok);
    const test::TowerSlot top = test::towerSlot(5, 0);
    // Along the top plank it lies on (along y), from 3 cm short of its
    // centre at 0.3 m/s: it stops after v^2 / (2 mu g) = 9 mm, still on it.
    BrickPlacement slider = placement(
        "slider", {top.x, sliding ? top.y - 0.03 : top.y, top.z + kKaplaThickness}, top.yaw);
    if (sliding) slider.linear_velocity = Eigen::Vector3d(0.0, 0.3, 0.0);
    ASSERT_TRUE(world->addBrick(slider).ok);
    world->takeEvents();
    test::runFor(world.get(), 1.0);
    EXPECT_TRUE(wakesOf(world.get()).empty());
    for (int i = 0; i < 12; ++i) {
      const std::string id = "t" + std::to_string(i);
      EXPECT_EQ(test::snapshotOf(*world, id).state, BrickState::kStable) << id;
      EXPECT_EQ(test::displacement(*world, id), 0.0) << id;
    }
    if (sliding) {
      EXPECT_GT(test::displacement(*world, "slider"), 0.005);  // it did slide
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, LoadsInMode, ::testing::ValuesIn(test::modelModes()));

}  // namespace
}  // namespace brick_stack_sim
