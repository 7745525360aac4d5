// The what-if of BrickWorld::evaluatePlacement against statics, in a real
// world: a plank overhanging the table's edge carries a second plank as long
// as their common centre of mass stays over the table.
#include <algorithm>
#include <limits>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"
#include "support/modes.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;
using test::placement;

constexpr double kEdge = 0.6;  ///< The default table's +x edge [m].
/// The lower plank's centre: 20 mm inside the edge, 38.5 mm of it over the floor.
constexpr double kLowerX = kEdge - 0.02;

class PlacementEvaluation : public ::testing::Test {
 protected:
  void SetUp() override {
    world_ = test::makeWorld(test::optionsFor("com"));
    ASSERT_TRUE(world_->addBrick(placement("low", {kLowerX, 0, kKaplaThickness / 2})).ok);
    BrickSnapshot low;
    ASSERT_TRUE(world_->find("low", &low));
    ASSERT_EQ(low.state, BrickState::kStable);
    world_->takeEvents();
    before_ = test::fingerprint(*world_);
  }

  /// A plank crosswise on the lower one, centred at x [m].
  static BrickPlacement onTop(double x) {
    return placement("top", {x, 0, 1.5 * kKaplaThickness}, M_PI / 2);
  }

  std::unique_ptr<BrickWorld> world_;
  std::string before_;
};

TEST_F(PlacementEvaluation, ALoadWhoseCommonCentreStaysOverTheTableIsStable) {
  // Two equal masses at 0.58 and 0.615: their centre at 0.5975, 2.5 mm inside.
  PlacementReport report;
  ASSERT_TRUE(world_->evaluatePlacement(onTop(kLowerX + 0.035), &report).ok);
  EXPECT_TRUE(report.stable) << report.reason;
  EXPECT_EQ(report.state, BrickState::kStable);
  EXPECT_EQ(report.supported_by, std::vector<std::string>{"low"});
  EXPECT_TRUE(report.would_fall.empty());
  EXPECT_NEAR(report.margin, test::kKaplaWidth / 2, 1e-6);
  EXPECT_TRUE(test::fingerprint(*world_) == before_) << "a query changed the world";
  EXPECT_TRUE(world_->takeEvents().empty());
}

TEST_F(PlacementEvaluation, ALoadThatMovesTheCommonCentrePastTheEdgeTipsTheLowerPlank) {
  // 0.58 and 0.63: their centre at 0.605, 5 mm past the edge.
  PlacementReport report;
  ASSERT_TRUE(world_->evaluatePlacement(onTop(kLowerX + 0.05), &report).ok);
  EXPECT_FALSE(report.stable);
  EXPECT_EQ(report.would_fall, std::vector<std::string>{"low"});
  EXPECT_NE(report.reason.find("low"), std::string::npos) << report.reason;
  EXPECT_TRUE(test::fingerprint(*world_) == before_) << "a query changed the world";
  // Placed for real, the lower plank is woken as the query said.
  ASSERT_TRUE(world_->addBrick(onTop(kLowerX + 0.05)).ok);
  BrickSnapshot low;
  ASSERT_TRUE(world_->find("low", &low));
  EXPECT_EQ(low.state, BrickState::kDynamic);
}

TEST_F(PlacementEvaluation, BadPlacementsAreRefused) {
  PlacementReport report;
  EXPECT_FALSE(world_->evaluatePlacement(placement("low", {0, 0.2, 0.0039}), &report).ok);
  BrickPlacement inside = onTop(kLowerX);
  inside.pose.translation().z() = kKaplaThickness / 2;  // inside the lower plank
  const Status overlap = world_->evaluatePlacement(inside, &report);
  EXPECT_FALSE(overlap.ok);
  EXPECT_NE(overlap.message.find("overlaps"), std::string::npos) << overlap.message;
  const Status under = world_->evaluatePlacement(placement("u", {0, 0, -0.01}), &report);
  EXPECT_FALSE(under.ok);
  EXPECT_NE(under.message.find("below the table"), std::string::npos) << under.message;
  EXPECT_TRUE(test::fingerprint(*world_) == before_);
}

TEST(PlacementStatics, PlainBulletIsAnsweredByStaticsToo) {
  auto plain = test::makeWorld(test::plainBulletOptions());
  const std::string before = test::fingerprint(*plain);
  PlacementReport report;
  ASSERT_TRUE(plain->evaluatePlacement(placement("a", {0, 0, kKaplaThickness / 2}), &report).ok);
  EXPECT_TRUE(report.stable) << report.reason;
  EXPECT_EQ(report.state, BrickState::kStable);
  EXPECT_EQ(report.supported_by, std::vector<std::string>{"table"});
  // Flat on the table it slides before it tips (half-thickness over
  // half-width is 1/3, over half-length 1/15): mu g, mu = 0.5 brick and table.
  EXPECT_NEAR(report.acceleration_margin, 0.5 * 9.81, 1e-6);
  // Half a millimetre above the table it touches nothing.
  ASSERT_TRUE(
      plain->evaluatePlacement(placement("a", {0, 0, kKaplaThickness / 2 + 5e-4}), &report).ok);
  EXPECT_FALSE(report.stable);
  EXPECT_TRUE(report.supported_by.empty());
  EXPECT_TRUE(test::fingerprint(*plain) == before) << "a query changed the world";
}

TEST(PlacementStatics, ALeaningPlankIsJudgedByFriction) {
  // Standing on its end, its COM L/2 above an edge T/2 away, a plank tips
  // at a sideways acceleration of g (T/2) / (L/2) = g T / L, before it
  // slides (mu g). Tilted by 0.3 rad with nothing to lean on, it falls.
  auto world = test::makeWorld(test::optionsFor("equilibrium"));
  PlacementReport report;
  BrickPlacement on_end = placement("a", {0, 0, test::kKaplaLength / 2});
  on_end.pose.linear() = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  ASSERT_TRUE(world->evaluatePlacement(on_end, &report).ok);
  EXPECT_TRUE(report.stable) << report.reason;
  EXPECT_NEAR(report.acceleration_margin, 9.81 * kKaplaThickness / test::kKaplaLength, 1e-6);
  BrickPlacement leaning = on_end;
  leaning.pose.linear() =
      Eigen::AngleAxisd(0.3 - M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  leaning.pose.translation() = Eigen::Vector3d(
      0.0, 0.0, 0.5 * (kKaplaThickness * std::sin(0.3) + test::kKaplaLength * std::cos(0.3)));
  ASSERT_TRUE(world->evaluatePlacement(leaning, &report).ok);
  EXPECT_FALSE(report.stable) << report.reason;
  EXPECT_EQ(report.supported_by, std::vector<std::string>{"table"});
}

TEST(PlacementStatics, AFrozenBrickAboveDoesNotHoldAQueriedBrickDown) {
  // q along x at x = 0.7 L rests on b0 (|x| < L/2) over [0.2, 0.5] L: its
  // COM is 0.2 L beyond b0's edge. Its other end, [0.2, 0.4] L, lies under
  // a frozen cap across it (along y at x = 0.3 L, y = 0.45 L, on the column
  // d0, d1 along x at y = L/2). Held down there, q would stand: about b0's
  // edge its weight needs F (0.5 L - x_F) = m g 0.2 L, F >= 0.67 m g at
  // x_F <= 0.2 L. The cap can give at most what its own weight holds about
  // d1's edge at y = 0.4 L: m g 0.05 L / 0.375 L = 0.13 m g (it pivots
  // there, q pushing it at y <= 0.025 L). q tips: a brick above holds
  // nothing down beyond its own weight, so statics must not count on it.
  const double L = test::kKaplaLength;
  auto world = test::makeWorld(test::optionsFor("com"));
  const std::vector<BrickPlacement> frozen = {
      placement("b0", {0.0, 0.0, 0.5 * kKaplaThickness}),
      placement("d0", {0.3 * L, 0.5 * L, 0.5 * kKaplaThickness}),
      placement("d1", {0.3 * L, 0.5 * L, 1.5 * kKaplaThickness}),
      placement("cap", {0.3 * L, 0.45 * L, 2.5 * kKaplaThickness}, M_PI / 2)};
  for (const BrickPlacement& p : frozen) ASSERT_TRUE(world->addBrick(p).ok) << p.id;
  for (const BrickPlacement& p : frozen) {
    BrickSnapshot b;
    ASSERT_TRUE(world->find(p.id, &b));
    ASSERT_EQ(b.state, BrickState::kStable) << p.id;
  }
  const std::string before = test::fingerprint(*world);
  PlacementReport report;
  ASSERT_TRUE(
      world->evaluatePlacement(placement("q", {0.7 * L, 0.0, 1.5 * kKaplaThickness}), &report).ok);
  EXPECT_FALSE(report.stable) << report.reason;
  EXPECT_EQ(report.state, BrickState::kDynamic);
  // It touches both, and its COM is 0.2 L outside what carries it.
  EXPECT_EQ(report.supported_by, (std::vector<std::string>{"b0", "cap"}));
  EXPECT_NEAR(report.margin, -0.2 * L, 1e-6);
  EXPECT_TRUE(test::fingerprint(*world) == before) << "a query changed the world";
  // The control: moved back so that its COM is over b0 (x = 0.4 L), it
  // stands, the cap still touching it from above.
  ASSERT_TRUE(
      world->evaluatePlacement(placement("q", {0.4 * L, 0.0, 1.5 * kKaplaThickness}), &report).ok);
  EXPECT_TRUE(report.stable) << report.reason;
  EXPECT_EQ(report.state, BrickState::kStable);
}

}  // namespace
}  // namespace brick_stack_sim

namespace brick_stack_sim {
namespace {

/// A frozen staircase of planks along x, each `step` further out than the
/// one below; a plank queried on top at x. By statics (every plank a lever
/// about the edge of the one below, friction never asked), the stair with
/// the new plank stands while, for every plank k >= 1, the common centre of
/// k and of everything above it, the new plank included, lies over plank
/// k - 1 (within L / 2 of its centre); plank 0 lies well inside the table.
class StaircaseQuery : public ::testing::TestWithParam<std::string> {
 protected:
  static constexpr int kLevels = 8;
  static constexpr double kStep = 0.012;  ///< [m]

  void SetUp() override {
    world_ = test::makeWorld(test::optionsFor(GetParam()));
    for (int k = 0; k < kLevels; ++k) {
      ASSERT_TRUE(world_
                      ->addBrick(placement("s" + std::to_string(k),
                                           {levelX(k), 0.0, (k + 0.5) * kKaplaThickness}))
                      .ok);
    }
    for (int k = 0; k < kLevels; ++k) {
      BrickSnapshot brick;
      ASSERT_TRUE(world_->find("s" + std::to_string(k), &brick));
      ASSERT_EQ(brick.state, BrickState::kStable) << brick.id;
    }
  }

  static double levelX(int k) { return k * kStep; }

  /// The largest x of the new plank by statics [m], and the plank that
  /// tips first beyond it (kLevels: the new plank itself): the least over
  /// k of n_k (x_{k-1} + L/2) - (x_k + ... + x_top), n_k the planks from k
  /// up, the new one included.
  static double limit(int* first_to_tip) {
    double best = std::numeric_limits<double>::infinity();
    for (int k = 1; k <= kLevels; ++k) {
      double sum = 0.0;
      for (int j = k; j < kLevels; ++j) sum += levelX(j);
      const double n = kLevels - k + 1;
      const double x = n * (levelX(k - 1) + test::kKaplaLength / 2) - sum;
      if (x < best) best = x, *first_to_tip = k;
    }
    return best;
  }

  PlacementReport query(double x) {
    PlacementReport report;
    EXPECT_TRUE(world_
                    ->evaluatePlacement(placement("q", {x, 0.0, (kLevels + 0.5) * kKaplaThickness}),
                                        &report)
                    .ok);
    return report;
  }

  std::unique_ptr<BrickWorld> world_;
};

TEST_P(StaircaseQuery, TheLoadOfANewPlankIsJudgedOnEveryLevelBelow) {
  int first = -1;
  const double x_max = limit(&first);
  // With 12 mm steps the stair's own weight leaves the lowest planks the
  // least room: the limit is set well below the top, by plank 1 on plank 0
  // (x_max = 8 (0 + 58.5) - 12 (1 + ... + 7) = 132 mm).
  ASSERT_EQ(first, 1);
  ASSERT_NEAR(x_max, 0.132, 1e-12);
  const std::string before = test::fingerprint(*world_);
  for (double inside : {0.02, 0.005, 0.0005}) {
    const PlacementReport report = query(x_max - inside);
    EXPECT_TRUE(report.stable) << inside << ": " << report.reason;
    EXPECT_TRUE(report.would_fall.empty()) << inside;
    EXPECT_EQ(report.supported_by, std::vector<std::string>{"s" + std::to_string(kLevels - 1)});
  }
  for (double beyond : {0.0005, 0.005}) {
    const PlacementReport report = query(x_max + beyond);
    EXPECT_FALSE(report.stable) << beyond;
    // Everything from the plank that tips up tips with it.
    std::vector<std::string> expected;
    for (int k = first; k < kLevels; ++k) expected.push_back("s" + std::to_string(k));
    std::sort(expected.begin(), expected.end());
    std::vector<std::string> fell = report.would_fall;
    std::sort(fell.begin(), fell.end());
    EXPECT_EQ(fell, expected) << beyond << ": " << report.reason;
  }
  EXPECT_TRUE(test::fingerprint(*world_) == before) << "a query changed the world";
}

INSTANTIATE_TEST_SUITE_P(Modes, StaircaseQuery, ::testing::ValuesIn(test::modelModes()),
                         test::modeName);

}  // namespace
}  // namespace brick_stack_sim

namespace brick_stack_sim {
namespace {

/// `p` turned by `angle` [rad] about the y axis through its centre.
BrickPlacement tilted(BrickPlacement p, double angle) {
  p.pose.linear() = p.pose.linear() * Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).matrix();
  return p;
}

TEST(PlacementStatics, LevelSupportsAreJudgedInClosedFormAsTheLpJudgesThem) {
  // A brick placed level on level supports is judged without the LP; tilted
  // by 0.1 micro-radian it goes to the LP. The two must agree: the same
  // verdict, and the same least acceleration to within what the tilt moves.
  auto world = test::makeWorld(test::optionsFor("com"));
  ASSERT_TRUE(world->addBrick(placement("a", {0.0, 0.0, 0.5 * kKaplaThickness})).ok);
  ASSERT_TRUE(world->addBrick(placement("b", {0.0, 0.08, 0.5 * kKaplaThickness})).ok);
  const double on_one = 1.5 * kKaplaThickness;
  std::vector<BrickPlacement> queries = {
      placement("q", {0.2, 0.0, 0.5 * kKaplaThickness}),      // on the table
      placement("q", {0.0, 0.0, on_one}),                     // on a, flush
      placement("q", {0.05, 0.0, on_one}),                    // on a, 50 mm out
      placement("q", {0.065, 0.0, on_one}),                   // its COM beyond a
      placement("q", {0.0, 0.01, on_one}),                    // on a, 10 mm aside
      placement("q", {0.0, 0.04, on_one}, M_PI / 2),          // across a and b
      placement("q", {0.03, 0.045, on_one}, M_PI / 2 + 0.3),  // askew across both
      placement("q", {-0.04, -0.004, on_one}, 0.7),           // turned on a
  };
  BrickPlacement upright = placement("q", {0.2, 0.1, 0.5 * test::kKaplaLength});
  upright.pose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).matrix();
  queries.push_back(upright);
  int stood = 0;
  for (const BrickPlacement& level : queries) {
    PlacementReport closed, by_lp;
    ASSERT_TRUE(world->evaluatePlacement(level, &closed).ok);
    ASSERT_TRUE(world->evaluatePlacement(tilted(level, 1e-7), &by_lp).ok);
    const std::string where = std::to_string(level.pose.translation().x()) + ", " +
                              std::to_string(level.pose.translation().y());
    EXPECT_EQ(closed.stable, by_lp.stable)
        << where << ": " << closed.reason << " / " << by_lp.reason;
    EXPECT_EQ(closed.supported_by, by_lp.supported_by) << where;
    EXPECT_NEAR(closed.acceleration_margin, by_lp.acceleration_margin,
                1e-4 * by_lp.acceleration_margin + 1e-6)
        << where;
    stood += closed.stable;
  }
  // All but the plank 65 mm out, its COM 6.5 mm beyond a's end, stand.
  EXPECT_EQ(stood, static_cast<int>(queries.size()) - 1);
}

}  // namespace
}  // namespace brick_stack_sim
