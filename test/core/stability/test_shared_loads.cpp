// Loads shared among several supporters, judged by statics: corbel arches
// just inside and just past their limit, and a plank bridging a cantilever
// and a tower, asked of ~query_placement on a grid of poses. Where one load
// rests on several supports, rigid-block statics may share it in any way
// the contacts admit, and a structure stands when one sharing holds every
// brick; each limit below is derived by hand in its comments.

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/kapla.h"
#include "support/world_probe.h"
#include "support/modes.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaThickness;
using test::kKaplaWidth;
using test::placement;

constexpr double kAlongY = M_PI / 2.0;  ///< Yaw that lays a KAPLA along y.

// --- corbel arches -------------------------------------------------------------

/// A corbel arch of KAPLAs along x: two mirrored half-stacks of `steps`
/// bricks, each brick `step` [m] further in than the one under it, the inner
/// ends of the two top bricks a gap G = L / 2 apart, and a cap across them.
/// Half l: brick k at x_k = x_0 + k s with x_{n-1} + L / 2 = -G / 2.
constexpr double kArchGap = 0.5 * kKaplaLength;

std::vector<BrickPlacement> corbelArch(int steps, double step) {
  const double x0 = -0.5 * kArchGap - 0.5 * kKaplaLength - (steps - 1) * step;
  std::vector<BrickPlacement> bricks;
  for (int k = 0; k < steps; ++k) {
    const double x = x0 + k * step, z = (k + 0.5) * kKaplaThickness;
    bricks.push_back(placement("l" + std::to_string(k), {x, 0.0, z}));
    bricks.push_back(placement("r" + std::to_string(k), {-x, 0.0, z}));
  }
  bricks.push_back(placement("cap", {0.0, 0.0, (steps + 0.5) * kKaplaThickness}));
  return bricks;
}

/// Whether statics admits the arch. By symmetry each half carries half the
/// cap's weight V = m g / 2 through the cap's end, which lies over the top
/// brick at x = -L / 2 (for the left half, "in" is +x), best as far out as
/// it can act: at the cap's end; and friction there may push the half's top
/// outwards with H <= mu V, the cap squeezed between the halves. For every
/// k the bricks k..n-1 with V and H press on what is under them (brick k-1,
/// or the table for k = 0) where their resultant crosses z = k T: at
///   x_r = (sum_{j >= k} m g x_j + V x_V - H (n - k) T) / ((n - k) m g + V),
/// which must lie on the patch they share, [x_k - L/2, x_{k-1} + L/2] (for
/// k = 0 the brick's own bottom, [x_0 - L/2, x_0 + L/2]). Each k bounds H
/// from both sides; the arch stands when some H in [0, mu V] meets all.
bool archStands(int steps, double step, double mu) {
  const double x0 = -0.5 * kArchGap - 0.5 * kKaplaLength - (steps - 1) * step;
  const double half_cap = 0.5;  // V in units of one brick's weight
  double least_h = 0.0, most_h = mu * half_cap;
  for (int k = 0; k < steps; ++k) {
    const double inner = (k > 0 ? x0 + (k - 1) * step : x0) + 0.5 * kKaplaLength;
    const double outer = x0 + k * step - 0.5 * kKaplaLength;
    double moment = -half_cap * 0.5 * kKaplaLength;  // V at x_V = -L / 2
    for (int j = k; j < steps; ++j) moment += x0 + j * step;
    const double weight = (steps - k) + half_cap;
    const double lever = (steps - k) * kKaplaThickness;
    // outer <= (moment - H lever) / weight <= inner
    least_h = std::max(least_h, (moment - inner * weight) / lever);
    most_h = std::min(most_h, (moment - outer * weight) / lever);
  }
  return least_h <= most_h;
}

/// The largest step at which the arch stands (bisection on archStands) [m].
double archLimit(int steps, double mu) {
  double stands = 0.0, falls = 0.5 * kKaplaLength;
  for (int i = 0; i < 60; ++i) {
    const double middle = 0.5 * (stands + falls);
    (archStands(steps, middle, mu) ? stands : falls) = middle;
  }
  return stands;
}

class SharedLoadsInMode : public ::testing::TestWithParam<std::string> {};

TEST(CorbelArchStatics, TheLimitIsWhereTheCapsThrustNoLongerHoldsTheHalves) {
  // Without the cap each half stands while its bricks' COM stays over the
  // bottom brick's inner end: s <= L / n (16.7 mm for 7, 14.6 mm for 8);
  // the cap's weight pushes the halves in, its friction thrust holds them.
  EXPECT_NEAR(archLimit(7, 0.5), 0.015722, 2e-6);
  EXPECT_NEAR(archLimit(8, 0.5), 0.013898, 2e-6);
  EXPECT_LT(archLimit(7, 0.0), archLimit(7, 0.5));  // the thrust is worth something
  EXPECT_LT(archLimit(7, 0.5), kKaplaLength / 7);
}

TEST_P(SharedLoadsInMode, CorbelArchesStandJustInsideTheirLimitAndFallJustPastIt) {
  for (int steps : {7, 8}) {
    for (double fraction : {0.93, 1.015}) {
      SCOPED_TRACE(std::to_string(steps) + " steps at " + std::to_string(fraction));
      const std::vector<BrickPlacement> arch = corbelArch(steps, fraction * archLimit(steps, 0.5));
      auto world = test::worldWithFriction(GetParam(), 0.5);
      for (const BrickPlacement& brick : arch) ASSERT_TRUE(world->addBrick(brick).ok) << brick.id;
      test::runFor(world.get(), 2.0);
      std::map<std::string, int> wakes, freezes;
      for (const SimEvent& e : world->takeEvents()) {
        if (e.kind == SimEventKind::kWoken) ++wakes[e.brick_id];
        if (e.kind == SimEventKind::kFrozen) ++freezes[e.brick_id];
      }
      if (fraction < 1.0) {
        EXPECT_TRUE(wakes.empty());
        for (const BrickPlacement& brick : arch) {
          EXPECT_EQ(test::snapshotOf(*world, brick.id).state, BrickState::kStable) << brick.id;
          EXPECT_EQ(test::displacement(*world, brick.id), 0.0) << brick.id;
        }
        continue;
      }
      // The halves tip in and the cap drops: what rests on the bottom
      // bricks goes, and no brick freezes where it was woken to wake again.
      EXPECT_GT(test::displacement(*world, "cap"), 0.005);
      for (const char* half : {"l", "r"})
        EXPECT_GT(test::displacement(*world, half + std::to_string(steps - 1)), 0.005) << half;
      for (const auto& [id, count] : wakes) EXPECT_EQ(count, 1) << id << " woke again";
      for (const auto& [id, count] : freezes) EXPECT_LE(count, 2) << id << " froze again and again";
      EXPECT_EQ(world->cost().wake_cycles, 0u);
    }
  }
}

// --- a plank bridging a cantilever and a tower, asked of the what-if ----------

/// Frictionless, so that the sharing is all in the vertical forces: the base
/// S along x on the table, its end at x_e; A along x on S, its centre c =
/// 5 mm inside x_e (a cantilever); B, a tower of two KAPLAs along x beside
/// them at y = +W, reaching past x_e. A lies at y = -W. The bridge goes
/// along y across A and B at x = x_b, centred at y = 0, on top.
constexpr double kBaseEnd = 0.0;
constexpr double kCantileverInside = 0.005;

std::unique_ptr<BrickWorld> cantileverAndTower(const std::string& mode) {
  auto world = test::worldWithFriction(mode, 0.0);
  const double t = kKaplaThickness, w = kKaplaWidth;
  EXPECT_TRUE(world->addBrick(placement("S", {kBaseEnd - 0.5 * kKaplaLength, -w, 0.5 * t})).ok);
  EXPECT_TRUE(
      world
          ->addBrick(placement("A", {kBaseEnd - kCantileverInside, -w, 1.5 * t}))
          .ok);
  for (int level = 0; level < 2; ++level)
    EXPECT_TRUE(world->addBrick(placement("B" + std::to_string(level),
                                          {kBaseEnd + 0.03, w, (level + 0.5) * t}))
                    .ok);
  for (const char* id : {"S", "A", "B0", "B1"})
    EXPECT_EQ(test::snapshotOf(*world, id).state, BrickState::kStable) << id;
  return world;
}

TEST_P(SharedLoadsInMode, AQueryAgreesWithStaticsOnAPlankBridgingACantileverAndATower) {
  // The bridge (weight m g, like every KAPLA) rests on A's and B's top
  // patches, each W wide in x and in y. Statics may put A's share R_A
  // anywhere in A's patch and B's in B's: the least R_A is with A's force at
  // A's far side (y = -3W/2) and B's at B's near side (y = W/2): moments
  // about the bridge's centre give R_A = m g (W/2) / (2W) = m g / 4. And A's
  // force may act at the near edge of its patch, x_b - W/2, with B's at
  // x_b + W/6 in its own patch. A (its COM c inside S's end x_e) then
  // tips about x_e when (m g / 4)(x_b - W/2 - x_e) > m g c:
  //   x_b* = x_e + W/2 + 4 c = x_e + 31.7 mm.
  // Splitting the bridge at the patch centres would put half of it at x_b,
  // and tip A from x_e + 2 c = x_e + 10 mm on.
  const double threshold = kBaseEnd + 0.5 * kKaplaWidth + 4.0 * kCantileverInside;
  auto world = cantileverAndTower(GetParam());
  const std::string before = test::fingerprint(*world);
  std::vector<double> offsets;  // from the threshold [m]
  for (double d = -0.012; d <= 0.0101; d += 0.001) offsets.push_back(d);
  for (double d : {-0.0008, -0.0004, -0.0002, -0.0001, 0.0001, 0.0002, 0.0004, 0.0008})
    offsets.push_back(d);
  for (double offset : offsets) {
    if (std::abs(offset) < 5e-5) continue;  // at the threshold itself either answer is statics'
    const double x_b = threshold + offset;
    SCOPED_TRACE("bridge at x_e + " + std::to_string((x_b - kBaseEnd) * 1e3) + " mm");
    PlacementReport report;
    ASSERT_TRUE(world
                    ->evaluatePlacement(
                        placement("bridge", {x_b, 0.0, 2.5 * kKaplaThickness}, kAlongY), &report)
                    .ok);
    EXPECT_EQ(report.supported_by, (std::vector<std::string>{"A", "B1"}));
    if (offset < 0.0) {
      EXPECT_TRUE(report.stable) << report.reason;
      EXPECT_TRUE(report.would_fall.empty());
    } else {
      EXPECT_FALSE(report.stable);
      EXPECT_EQ(report.would_fall, std::vector<std::string>{"A"}) << report.reason;
    }
  }
  EXPECT_TRUE(test::fingerprint(*world) == before) << "a query changed the world";
}

INSTANTIATE_TEST_SUITE_P(Modes, SharedLoadsInMode, ::testing::ValuesIn(test::modelModes()));

}  // namespace
}  // namespace brick_stack_sim
