// The statics LP against cases with exact answers (docs/testing.md, "Ground truth"),
// each derived by hand in support/leaning.h or below. Contacts come from
// the boxes' geometry (touchingContacts), as for a brick placed at rest.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/box_contact.h"
#include "stability/rigid_block_statics.h"
#include "support/leaning.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaMass;
using test::kKaplaThickness;

/// Bricks (boxes) on a table, every touching pair a contact with one friction.
class StaticsScene {
 public:
  explicit StaticsScene(double friction) : friction_(friction) {}

  int add(const Eigen::Isometry3d& pose, double mass = kKaplaMass, bool fixed = false,
          Eigen::Vector3d half_extents = test::kaplaHalfExtents()) {
    boxes_.push_back(OrientedBox{pose, half_extents});
    bodies_.push_back(StaticsBody{mass, pose.translation(), fixed});
    return static_cast<int>(bodies_.size()) - 1;
  }
  /// A load on `body` from outside the problem: `force` [N] at `point`.
  void applyLoad(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& point) {
    bodies_[body].applied_force += force;
    bodies_[body].applied_torque += (point - bodies_[body].com).cross(force);
  }
  /// The friction of the pair (i, j) when it differs from the scene's.
  void setFriction(int i, int j, double friction) { pair_friction_.push_back({i, j, friction}); }

  std::vector<StaticsContact> contacts() const {
    const OrientedBox table = test::tableBox();
    std::vector<StaticsContact> result;
    auto add_pair = [&](int a, int b, const OrientedBox& box_b) {
      for (const BoxContactFace& face : touchingContacts(boxes_[a], box_b, 1e-7))
        for (const Eigen::Vector3d& point : face.points)
          result.push_back(StaticsContact{a, b, point, face.normal, frictionOf(a, b)});
    };
    for (int a = 0; a < static_cast<int>(boxes_.size()); ++a) {
      add_pair(a, kStaticsGround, table);
      for (int b = 0; b < a; ++b) add_pair(a, b, boxes_[b]);
    }
    return result;
  }

  StaticsSolution solve(const StaticsOptions& options = StaticsOptions()) const {
    return solveStatics(bodies_, contacts(), options);
  }
  bool stands() const {
    const StaticsSolution solution = solve();
    EXPECT_TRUE(solution.solved) << solution.message;
    return solution.feasible;
  }

 private:
  double frictionOf(int a, int b) const {
    for (const auto& [i, j, friction] : pair_friction_)
      if ((i == a && j == b) || (i == b && j == a)) return friction;
    return friction_;
  }
  struct PairFriction {
    int i, j;
    double friction;
  };
  double friction_;
  std::vector<OrientedBox> boxes_;
  std::vector<StaticsBody> bodies_;
  std::vector<PairFriction> pair_friction_;
};

Eigen::Isometry3d flatAt(double x, double z) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, 0.0, z);
  return pose;
}

TEST(RigidBlockStatics, BrickOnTheTableStandsAndNothingLeftIsFree) {
  StaticsScene scene(0.5);
  scene.add(flatAt(0.0, 0.5 * kKaplaThickness));
  const StaticsSolution solution = scene.solve();
  ASSERT_TRUE(solution.solved);
  EXPECT_TRUE(solution.feasible);
  // The table carries the weight: the forces sum to m g up.
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& f : solution.forces) total += f;
  EXPECT_NEAR(total.z(), kKaplaMass * 9.81, 1e-9);
  EXPECT_NEAR(total.head<2>().norm(), 0.0, 1e-9);
}

TEST(RigidBlockStatics, BrickInTheAirIsTheOneThatMustMove) {
  StaticsScene scene(0.5);
  const int resting = scene.add(flatAt(0.0, 0.5 * kKaplaThickness));
  const int floating = scene.add(flatAt(0.3, 0.05));
  const StaticsSolution solution = scene.solve();
  EXPECT_FALSE(solution.feasible);
  EXPECT_EQ(solution.imbalance[resting], 0.0);
  // Its whole weight is unbalanced, 1 in units of the heaviest weight.
  EXPECT_NEAR(solution.imbalance[floating], 1.0, 1e-9);
}

class VOfPlanks : public ::testing::TestWithParam<double> {};

TEST_P(VOfPlanks, StandsBelowTheThresholdAngleAndFallsAbove) {
  const double mu = GetParam();
  const double threshold = test::vThresholdAngle(mu);
  for (double factor : {0.9, 1.1}) {
    StaticsScene scene(mu);
    const auto [left, right] = test::vPlanks(factor * threshold);
    scene.add(left);
    scene.add(right);
    EXPECT_EQ(scene.stands(), factor < 1.0) << "mu " << mu << ", " << factor << " x threshold";
  }
}

INSTANTIATE_TEST_SUITE_P(TwoFrictions, VOfPlanks, ::testing::Values(0.3, 0.5));

TEST(RigidBlockStatics, OnePlankOfAVAloneFalls) {
  StaticsScene scene(0.5);
  scene.add(test::vPlanks(0.5).first);
  EXPECT_FALSE(scene.stands());
}

/// A plank lying on a fixed slab tilted by `tilt` about a horizontal axis,
/// the slope's downhill direction at `heading` from the world x axis.
StaticsScene plankOnATiltedSlab(double mu, double tilt, double heading) {
  StaticsScene scene(mu);
  Eigen::Isometry3d slab = Eigen::Isometry3d::Identity();
  slab.linear() = (Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()))
                      .toRotationMatrix();
  slab.translation() = Eigen::Vector3d(0.0, 0.0, 0.3);  // clear of the table
  const Eigen::Vector3d slab_half(0.2, 0.2, 0.01);
  scene.add(slab, 10 * kKaplaMass, /*fixed=*/true, slab_half);
  Eigen::Isometry3d plank = slab;
  plank.translation() +=
      slab.linear() * Eigen::Vector3d(0.0, 0.0, slab_half.z() + 0.5 * kKaplaThickness);
  scene.add(plank);
  return scene;
}

TEST(RigidBlockStatics, FrictionHoldsAPlankOnASlopeUpToTheFrictionAngleInAnyHeading) {
  // Coulomb: a block on an incline stands while tan(tilt) < mu, whatever
  // way the slope faces. The pyramid cut from the cone must not refuse
  // it short of that (a heading between two of its edges once held only
  // cos(pi / 8) of mu, 7.6 % short).
  const double mu = 0.5;
  const double friction_angle = std::atan(mu);
  for (double heading : {0.0, M_PI / 8.0, 1.0, 0.75 * M_PI}) {
    for (double factor : {0.97, 1.03}) {
      const StaticsScene scene = plankOnATiltedSlab(mu, factor * friction_angle, heading);
      EXPECT_EQ(scene.stands(), factor < 1.0)
          << "heading " << heading << ", " << factor << " x the friction angle";
    }
  }
}

class Ladder : public ::testing::TestWithParam<double> {};

TEST_P(Ladder, PlankAgainstAHeavyBlockStandsByItsOwnFormula) {
  const double mu = 0.4, mu_wall = GetParam();
  const double threshold = test::ladderThresholdAngle(mu, mu_wall);
  for (double factor : {0.9, 1.1}) {
    StaticsScene scene(mu);
    const int plank = scene.add(test::plankLeaningTowardsX(factor * threshold, 0.0));
    // A block of 50 plank masses whose face is the plane x = 0: the wall.
    const Eigen::Vector3d wall_half(0.05, 0.05, 0.1);
    const int wall =
        scene.add(flatAt(wall_half.x(), wall_half.z()), 50 * kKaplaMass, false, wall_half);
    scene.setFriction(plank, wall, mu_wall);
    EXPECT_EQ(scene.stands(), factor < 1.0) << "wall friction " << mu_wall << ", " << factor;
  }
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutWallFriction, Ladder, ::testing::Values(0.0, 0.3));

/// `stacks` harmonic stacks of `n` free bricks side by side, 5 cm apart,
/// each on its own fixed base; stack `odd_one` (when >= 0) at `f_odd`, the
/// others at `f`. Returns the stack of each body (-1 for the bases).
StaticsScene harmonicStacksSideBySide(int stacks, int n, double f, int odd_one, double f_odd,
                                      std::vector<int>* stack_of) {
  StaticsScene scene(0.5);
  const double t = kKaplaThickness;
  for (int k = 0; k < stacks; ++k) {
    const double y = 0.05 * k;
    const double fk = k == odd_one ? f_odd : f;
    Eigen::Isometry3d pose = flatAt(0.0, 0.5 * t);
    pose.translation().y() = y;
    scene.add(pose, kKaplaMass, /*fixed=*/true);
    stack_of->push_back(-1);
    double x = 0.0;
    for (int i = n; i >= 1; --i) {
      x += fk * kKaplaLength / (2.0 * i);
      pose = flatAt(x, (n - i + 1.5) * t);
      pose.translation().y() = y;
      scene.add(pose);
      stack_of->push_back(k);
    }
  }
  return scene;
}

/// A harmonic stack (docs/testing.md, "Ground truth"): brick i from the top sits f L / (2 i)
/// beyond the one below it, the bottom one on the table's edge... here on a
/// fixed base brick. It stands for f < 1 and falls for f > 1.
bool harmonicStackStands(int n, double f) {
  std::vector<int> stack_of;
  return harmonicStacksSideBySide(1, n, f, -1, f, &stack_of).stands();
}

TEST(RigidBlockStatics, ProblemsOfHundredsOfBricksFindTheSameThresholdAsOneStack) {
  // 17 stacks of 12: 204 free bricks, the size of a settled pile's group,
  // which the LP solves another way than a stack of tens (an interior
  // point first, a vertex only when it does not balance). The threshold is
  // still the harmonic stack's, and a stack past it is the only one that
  // moves, with the least imbalance it has alone.
  constexpr int kStacks = 17, kBricks = 12;
  std::vector<int> stack_of;
  const StaticsScene standing =
      harmonicStacksSideBySide(kStacks, kBricks, 0.99, -1, 0.99, &stack_of);
  const StaticsSolution all_stand = standing.solve();
  ASSERT_TRUE(all_stand.solved) << all_stand.message;
  EXPECT_TRUE(all_stand.feasible);
  // The bases carry every free brick's weight.
  const std::vector<StaticsContact> contacts = standing.contacts();
  Eigen::Vector3d on_bases = Eigen::Vector3d::Zero();
  for (std::size_t c = 0; c < contacts.size(); ++c)
    if (contacts[c].b >= 0 && stack_of[contacts[c].b] < 0) on_bases += all_stand.forces[c];
  EXPECT_NEAR(on_bases.z(), kStacks * kBricks * kKaplaMass * 9.81, 1e-6);
  EXPECT_NEAR(on_bases.head<2>().norm(), 0.0, 1e-6);

  stack_of.clear();
  const StaticsSolution one_falls =
      harmonicStacksSideBySide(kStacks, kBricks, 0.99, 5, 1.01, &stack_of).solve();
  std::vector<int> alone_of;
  const StaticsSolution alone =
      harmonicStacksSideBySide(1, kBricks, 1.01, 0, 1.01, &alone_of).solve();
  ASSERT_TRUE(one_falls.solved) << one_falls.message;
  ASSERT_TRUE(alone.solved);
  EXPECT_FALSE(one_falls.feasible);
  EXPECT_FALSE(alone.feasible);
  double total_imbalance = 0.0, alone_imbalance = 0.0;
  int moving = 0;
  for (std::size_t i = 0; i < stack_of.size(); ++i) {
    total_imbalance += one_falls.imbalance[i];
    if (!one_falls.moves[i]) continue;
    ++moving;
    EXPECT_EQ(stack_of[i], 5) << "body " << i;
  }
  for (double v : alone.imbalance) alone_imbalance += v;
  EXPECT_GT(moving, 0);
  EXPECT_NEAR(total_imbalance, alone_imbalance, 1e-6);
}

TEST(RigidBlockStatics, HarmonicStacksFindTheirThresholdWithinOnePercent) {
  for (int n : {4, 8, 12}) {
    EXPECT_TRUE(harmonicStackStands(n, 0.99)) << n << " bricks";
    EXPECT_FALSE(harmonicStackStands(n, 1.01)) << n << " bricks";
  }
}

/// Bricks of one KAPLA each, flat, one per level from the table up, centred
/// at `x[i]` (fractions of L).
bool flatStackStands(const std::vector<double>& x) {
  StaticsScene scene(0.5);
  for (std::size_t level = 0; level < x.size(); ++level)
    scene.add(flatAt(x[level] * kKaplaLength, (level + 0.5) * kKaplaThickness));
  return scene.stands();
}

TEST(RigidBlockStatics, CounterweightsHoldOverhangsThatFallWithoutThem) {
  // Base at 0 (its edge at 0.5 L); a plank at 0.7 L overhangs it, its COM
  // 0.2 L past the edge. A counterweight at 0.25 L on its inner end (0.05 L
  // inside its end at 0.2 L) brings the pair's COM to 0.475 L, inside.
  EXPECT_TRUE(flatStackStands({0.0, 0.7, 0.25}));
  EXPECT_FALSE(flatStackStands({0.0, 0.7}));
  // Four: the plank at 0.75 L, a counterweight at 0.35 L (pair COM 0.55 L:
  // out) and a second on it at 0.25 L: the three at 0.45 L, inside; the two
  // counterweights at 0.3 L, inside the plank's end at 0.25 L.
  EXPECT_TRUE(flatStackStands({0.0, 0.75, 0.35, 0.25}));
  EXPECT_FALSE(flatStackStands({0.0, 0.75, 0.35}));
}

TEST(RigidBlockStatics, AppliedLoadsTipABrickOnItsEndAtTheLeverRule) {
  // A push H along x on the top of a KAPLA standing on its end (height L,
  // thickness T along x) tips it about its far edge once H L > m g T / 2;
  // it would slide only at mu m g = 0.5 m g, far beyond.
  const double g = 9.81, tipping = kKaplaMass * g * 0.5 * kKaplaThickness / kKaplaLength;
  // Centred on x = 0.
  const Eigen::Isometry3d on_end = test::plankLeaningTowardsX(0.0, 0.5 * kKaplaThickness);
  for (double factor : {0.95, 1.05}) {
    StaticsScene scene(0.5);
    const int brick = scene.add(on_end);
    scene.applyLoad(brick, Eigen::Vector3d(factor * tipping, 0.0, 0.0),
                    Eigen::Vector3d(0.0, 0.0, kKaplaLength));
    EXPECT_EQ(scene.stands(), factor < 1.0) << factor;
  }
  // Its own weight again pressing on the middle of its top doubles what
  // holds it: 1.9 times the push stands.
  StaticsScene pressed(0.5);
  const int brick = pressed.add(on_end);
  pressed.applyLoad(brick, Eigen::Vector3d(1.9 * tipping, 0.0, -kKaplaMass * g),
                    Eigen::Vector3d(0.0, 0.0, kKaplaLength));
  EXPECT_TRUE(pressed.stands());
}

TEST(RigidBlockStatics, AccelerationMarginIsWhereItSlidesOrTips) {
  // Flat on the table it slides first: mu g. On its end it tips about an
  // edge first: g (T/2) / (L/2), below mu g.
  const double mu = 0.5, g = 9.81;
  StaticsScene flat(mu);
  flat.add(flatAt(0.0, 0.5 * kKaplaThickness));
  std::vector<StaticsBody> bodies{
      {kKaplaMass, flatAt(0.0, 0.5 * kKaplaThickness).translation(), false}};
  EXPECT_NEAR(horizontalAccelerationMargin(bodies, flat.contacts(), Eigen::Vector3d::UnitX()),
              mu * g, 1e-6);
  StaticsScene standing(mu);
  const Eigen::Isometry3d on_end = test::plankLeaningTowardsX(0.0, 0.5 * kKaplaThickness);
  standing.add(on_end);
  bodies[0].com = on_end.translation();
  EXPECT_NEAR(horizontalAccelerationMargin(bodies, standing.contacts(), Eigen::Vector3d::UnitX()),
              g * kKaplaThickness / kKaplaLength, 1e-6);
}

/// A slant tower of `layers` KAPLAs, each `offset` [m] further along x, as
/// bodies and contacts keyed for a warm start (body i is key i; a contact
/// by its two bodies and its index among their points).
struct KeyedTower {
  std::vector<StaticsBody> bodies;
  std::vector<StaticsContact> contacts;
  StaticsWarmStart keys;
};

KeyedTower keyedSlantTower(int layers, double offset) {
  StaticsScene scene(0.5);
  for (int i = 0; i < layers; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(i * offset, 0.0, (i + 0.5) * kKaplaThickness);
    scene.add(pose);
  }
  KeyedTower tower;
  tower.contacts = scene.contacts();
  for (int i = 0; i < layers; ++i) {
    tower.bodies.push_back(
        StaticsBody{kKaplaMass, Eigen::Vector3d(i * offset, 0.0, (i + 0.5) * kKaplaThickness)});
    tower.keys.body_keys.push_back(static_cast<std::uint64_t>(i));
  }
  std::map<std::pair<int, int>, int> seen;
  for (const StaticsContact& c : tower.contacts) {
    const int index = seen[{c.a, c.b}]++;
    tower.keys.contact_keys.push_back((static_cast<std::uint64_t>(c.a + 1) << 40) ^
                                      (static_cast<std::uint64_t>(c.b + 2) << 20) ^
                                      static_cast<std::uint64_t>(index));
  }
  return tower;
}

TEST(RigidBlockStatics, AWarmStartAnswersTheSameInFewerPivots) {
  // A 30-layer tower at 3 mm per layer stands (the COM of layers 1..29
  // sits 45 mm past b0's centre, inside its edge at 58.5); with 45 layers
  // the COM of layers 1..44 sits 67.5 mm out: it does not. Each is solved
  // cold, and warm from the basis of the tower one layer lower.
  for (const int layers : {30, 45}) {
    SCOPED_TRACE(std::to_string(layers) + " layers");
    StaticsBasis basis;
    KeyedTower lower = keyedSlantTower(layers - 1, 0.003);
    lower.keys.basis = &basis;
    ASSERT_TRUE(solveStatics(lower.bodies, lower.contacts, StaticsOptions(), &lower.keys).solved);
    EXPECT_FALSE(basis.columns.empty());

    KeyedTower tower = keyedSlantTower(layers, 0.003);
    const StaticsSolution cold = solveStatics(tower.bodies, tower.contacts);
    tower.keys.basis = &basis;
    const StaticsSolution warm =
        solveStatics(tower.bodies, tower.contacts, StaticsOptions(), &tower.keys);
    ASSERT_TRUE(cold.solved);
    ASSERT_TRUE(warm.solved);
    EXPECT_EQ(warm.feasible, layers == 30);
    EXPECT_EQ(cold.feasible, warm.feasible);
    // The least total imbalance is unique even where its place is not.
    double cold_total = 0.0, warm_total = 0.0;
    for (double v : cold.imbalance) cold_total += v;
    for (double v : warm.imbalance) warm_total += v;
    EXPECT_NEAR(cold_total, warm_total, 1e-6);
    EXPECT_LT(warm.iterations, cold.iterations);
    RecordProperty("cold_pivots_" + std::to_string(layers), cold.iterations);
    RecordProperty("warm_pivots_" + std::to_string(layers), warm.iterations);
    std::printf("statics LP, %d-layer slant tower: %d pivots cold, %d warm\n", layers,
                cold.iterations, warm.iterations);
  }
}

TEST(RigidBlockStatics, ProblemsThatTakeTurnsEachStartWhereTheyEnded) {
  // Two groups of a pile are asked in turn every tick with one basis
  // between them: each must start from where it last ended, not from the
  // other's, which shares none of its names. Two towers under disjoint
  // names: the first asked again after the second needs (almost) no pivots.
  // Both stand: at 3 mm a layer the COM of layers 1..29 sits 45 mm past
  // b0's centre, at 1 mm that of layers 1..39 20 mm, inside its edge at
  // 58.5 mm.
  KeyedTower first = keyedSlantTower(30, 0.003);
  KeyedTower second = keyedSlantTower(40, 0.001);
  for (std::uint64_t& key : second.keys.body_keys) key += 1000;
  for (std::uint64_t& key : second.keys.contact_keys) key ^= std::uint64_t{1} << 60;
  StaticsBasis basis;
  first.keys.basis = second.keys.basis = &basis;
  const StaticsSolution cold =
      solveStatics(first.bodies, first.contacts, StaticsOptions(), &first.keys);
  const StaticsSolution between =
      solveStatics(second.bodies, second.contacts, StaticsOptions(), &second.keys);
  ASSERT_TRUE(between.solved);
  EXPECT_TRUE(between.feasible);
  const StaticsSolution again =
      solveStatics(first.bodies, first.contacts, StaticsOptions(), &first.keys);
  ASSERT_TRUE(cold.solved);
  ASSERT_TRUE(again.solved);
  EXPECT_TRUE(cold.feasible);
  EXPECT_TRUE(again.feasible);
  ASSERT_GT(cold.iterations, 10);
  EXPECT_LE(again.iterations, cold.iterations / 10);
  std::printf("statics LP asked again after another: %d pivots, %d the first time\n",
              again.iterations, cold.iterations);
}

}  // namespace
}  // namespace brick_stack_sim
