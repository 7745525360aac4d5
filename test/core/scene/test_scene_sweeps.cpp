// What parameter sweeps vary in a scene: the block_tower generator, whose
// toppling is known from statics before the run, the scene's `friction` and
// its `pose_noise`. Ground truth is recomputed here from the bricks' poses.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/generators.h"
#include "support/kapla.h"
#include "support/scenes.h"

namespace brick_stack_sim {
namespace {

using test::kCube;
using test::parsed;

/// Refused, with every word of `expected` in the message.
void expectRefused(const std::string& yaml, const std::vector<std::string>& expected) {
  Scene scene;
  const Status s = parseScene(yaml, "sweep", test::packageTypes(), &scene);
  ASSERT_FALSE(s.ok) << yaml;
  for (const std::string& word : expected)
    EXPECT_NE(s.message.find(word), std::string::npos) << yaml << ": " << s.message;
}

/// Statics of a stack of equal boxes with centres of mass at their centres,
/// written from the definition: level k is brick k-1 carrying bricks
/// k..n-1, its criticality the larger over x and y of the distance of their
/// common centre of mass from brick k-1's centre over its half extent.
std::vector<double> levelCriticalities(const std::vector<ScheduledBrick>& bricks,
                                       const Eigen::Vector3d& size) {
  std::vector<double> levels;
  for (std::size_t k = 1; k < bricks.size(); ++k) {
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
    for (std::size_t i = k; i < bricks.size(); ++i) com += bricks[i].placement.pose.translation();
    com /= static_cast<double>(bricks.size() - k);
    const Eigen::Vector3d lever = com - bricks[k - 1].placement.pose.translation();
    levels.push_back(
        std::max(std::abs(lever.x()) / (size.x() / 2), std::abs(lever.y()) / (size.y() / 2)));
  }
  return levels;
}

TEST(BlockTower, ItsMostCriticalLevelHasTheCriticalityAskedFor) {
  struct Case {
    int bricks;
    const char* type;
    Eigen::Vector3d size;
    double criticality;
  };
  const Eigen::Vector3d cube(kCube, kCube, kCube);
  const Eigen::Vector3d kapla(test::kKaplaLength, test::kKaplaWidth, test::kKaplaThickness);
  for (const Case& c :
       {Case{2, "cube", cube, 0.9}, Case{2, "cube", cube, 1.1}, Case{5, "cube", cube, 0.9},
        Case{5, "cube", cube, 1.1}, Case{50, "kapla", kapla, 0.5}}) {
    for (int seed : {0, 1, 12345}) {
      const Scene scene =
          parsed("generator: {name: block_tower, bricks: " + std::to_string(c.bricks) +
                 ", type: " + c.type + ", criticality: " + std::to_string(c.criticality) +
                 ", seed: " + std::to_string(seed) + ", origin: [0.1, -0.05], start: 2.5}\n");
      ASSERT_EQ(scene.bricks.size(), static_cast<std::size_t>(c.bricks));
      const std::vector<double> levels = levelCriticalities(scene.bricks, c.size);
      // The offsets are scaled in double precision: a few ulps of rounding.
      EXPECT_NEAR(*std::max_element(levels.begin(), levels.end()), c.criticality, 1e-12)
          << c.bricks << " " << c.type << " seed " << seed;
      for (std::size_t i = 0; i < scene.bricks.size(); ++i) {
        const ScheduledBrick& brick = scene.bricks[i];
        EXPECT_EQ(brick.placement.type, c.type);
        EXPECT_EQ(brick.at, 2.5);
        EXPECT_TRUE(brick.placement.linear_velocity.isZero());
        EXPECT_TRUE(brick.placement.pose.linear().isIdentity(0.0));  // as the type's frame lies
        // Stacked from the table top, each on the one below.
        EXPECT_NEAR(brick.placement.pose.translation().z(), (i + 0.5) * c.size.z(), 1e-15);
      }
      EXPECT_EQ(scene.bricks[0].placement.pose.translation().head<2>(),
                Eigen::Vector2d(0.1, -0.05));
    }
  }
}

TEST(BlockTower, TheSeedDrawsTheOffsetsAndKaplaIsTheDefault) {
  const Scene a = parsed("generator: {name: block_tower, seed: 3}\n");
  const Scene b = parsed("generator: {name: block_tower, seed: 3}\n");
  const Scene c = parsed("generator: {name: block_tower, seed: 4}\n");
  ASSERT_EQ(a.bricks.size(), 5u);  // the default
  EXPECT_EQ(a.bricks[0].placement.type, "kapla");
  EXPECT_EQ(a.bricks[3].placement.pose.matrix(), b.bricks[3].placement.pose.matrix());
  EXPECT_NE(a.bricks[3].placement.pose.translation(), c.bricks[3].placement.pose.translation());
  // The default criticality.
  const std::vector<double> levels = levelCriticalities(
      a.bricks, Eigen::Vector3d(test::kKaplaLength, test::kKaplaWidth, test::kKaplaThickness));
  EXPECT_NEAR(*std::max_element(levels.begin(), levels.end()), 0.9, 1e-12);
  // One brick has no level: it lies at the origin.
  const Scene one = parsed("generator: {name: block_tower, bricks: 1, origin: [0.2, 0.1]}\n");
  ASSERT_EQ(one.bricks.size(), 1u);
  EXPECT_EQ(one.bricks[0].placement.pose.translation(),
            Eigen::Vector3d(0.2, 0.1, test::kKaplaThickness / 2));
}

TEST(BlockTower, CountsWhatItBuildsAndRefusesBadParameters) {
  BlockTowerParams params;
  params.bricks = 17;
  std::vector<ScheduledBrick> bricks;
  ASSERT_TRUE(generateBlockTower(params, test::packageTypes(), &bricks).ok);
  EXPECT_EQ(brickCount(params), 17);
  EXPECT_EQ(bricks.size(), 17u);
  const std::string tower = "generator: {name: block_tower, ";
  expectRefused(tower + "bricks: 0}\n", {"block_tower bricks = 0", "[1, 50]"});
  expectRefused(tower + "bricks: 51}\n", {"bricks = 51"});
  expectRefused(tower + "criticality: 0}\n", {"criticality", "> 0"});
  expectRefused(tower + "criticality: -0.5}\n", {"criticality"});
  expectRefused(tower + "criticality: .nan}\n", {"criticality", "finite"});
  expectRefused(tower + "criticality: .inf}\n", {"criticality", "finite"});
  expectRefused(tower + "seed: -1}\n", {"seed", ">= 0"});
  expectRefused(tower + "seed: 1.5}\n", {"seed", "integer"});
  expectRefused(tower + "interval: 1}\n", {"unknown key 'interval'"});
  expectRefused(tower + "levels: 3}\n", {"unknown key 'levels'"});
  expectRefused(tower + "type: marble}\n", {"marble"});
  expectRefused(tower + "type: unit_cylinder}\n", {"unit_cylinder", "not a box"});
  expectRefused(tower + "start: -1}\n", {"start"});
  expectRefused(tower + "origin: [0, .nan]}\n", {"origin"});
}

/// The rotation about world z that takes `from` to `to` [rad]; fails the
/// test when the two differ by more than a turn about z.
double yawBetween(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to) {
  const Eigen::Matrix3d turn = to * from.transpose();
  EXPECT_NEAR(turn(2, 2), 1.0, 1e-12);
  return std::atan2(turn(1, 0), turn(0, 0));
}

const char* const kNoiseFree =
    "generator: {name: tower, layers: 3}\n"
    "bricks:\n"
    "  - {id: thrown, at: 0.5, position: [0.3, 0.2, 0.05], rpy: [0.1, 0.2, 0.3],\n"
    "     linear_velocity: [1, 0, 0]}\n";

TEST(PoseNoise, OffsetsAndTurnsEachBrickWithinItsBoundsAsDocumented) {
  const Scene base = parsed(kNoiseFree);
  const Scene noisy =
      parsed(std::string(kNoiseFree) + "pose_noise: {position: 0.002, yaw: 0.05, seed: 7}\n");
  ASSERT_EQ(noisy.bricks.size(), base.bricks.size());
  // The documented draws, rebuilt here: x, y and yaw per brick in the
  // scene's order, each the top 53 bits of std::mt19937_64 (a generator the
  // standard fixes bit for bit) mapped onto [-bound, bound).
  std::mt19937_64 random(7);
  auto within = [&random](double bound) {
    return bound * (2.0 * (static_cast<double>(random() >> 11) / 9007199254740992.0) - 1.0);
  };
  for (std::size_t i = 0; i < base.bricks.size(); ++i) {
    const Eigen::Isometry3d& was = base.bricks[i].placement.pose;
    const Eigen::Isometry3d& now = noisy.bricks[i].placement.pose;
    const double dx = within(0.002), dy = within(0.002), yaw = within(0.05);
    EXPECT_LE(std::abs(dx), 0.002);
    EXPECT_LE(std::abs(dy), 0.002);
    // The offset is added to the position: those bits exactly.
    EXPECT_EQ(now.translation().x(), was.translation().x() + dx);
    EXPECT_EQ(now.translation().y(), was.translation().y() + dy);
    EXPECT_EQ(now.translation().z(), was.translation().z());
    const double turn = yawBetween(was.linear(), now.linear());
    EXPECT_LE(std::abs(turn), 0.05 + 1e-12);
    EXPECT_NEAR(turn, yaw, 1e-12);
    // Placement times, ids and velocities are the scene's.
    EXPECT_EQ(noisy.bricks[i].placement.id, base.bricks[i].placement.id);
    EXPECT_EQ(noisy.bricks[i].at, base.bricks[i].at);
    EXPECT_EQ(noisy.bricks[i].placement.linear_velocity, base.bricks[i].placement.linear_velocity);
  }
  EXPECT_EQ(noisy.pose_noise->seed, 7u);
}

bool samePoseBits(const Scene& a, const Scene& b) {
  if (a.bricks.size() != b.bricks.size()) return false;
  for (std::size_t i = 0; i < a.bricks.size(); ++i)
    if (std::memcmp(a.bricks[i].placement.pose.data(), b.bricks[i].placement.pose.data(),
                    16 * sizeof(double)) != 0)
      return false;
  return true;
}

TEST(PoseNoise, TheSeedFixesThePosesBitForBitAndZeroNoiseLeavesThemAlone) {
  const std::string noise = "pose_noise: {position: 0.001, yaw: 0.02, seed: ";
  const Scene a = parsed(kNoiseFree + noise + "11}\n");
  const Scene b = parsed(kNoiseFree + noise + "11}\n");
  const Scene c = parsed(kNoiseFree + noise + "12}\n");
  EXPECT_TRUE(samePoseBits(a, b));
  EXPECT_FALSE(samePoseBits(a, c));
  for (std::size_t i = 0; i < a.bricks.size(); ++i)
    EXPECT_NE(a.bricks[i].placement.pose.translation(), c.bricks[i].placement.pose.translation());
  const Scene base = parsed(kNoiseFree);
  EXPECT_TRUE(samePoseBits(base, parsed(kNoiseFree + std::string("pose_noise: {seed: 5}\n"))));
  EXPECT_TRUE(samePoseBits(
      base, parsed(kNoiseFree + std::string("pose_noise: {position: 0, yaw: 0, seed: 5}\n"))));
  // A zero bound leaves the other draws as they were.
  const Scene only_yaw = parsed(kNoiseFree + std::string("pose_noise: {yaw: 0.02, seed: 11}\n"));
  for (std::size_t i = 0; i < a.bricks.size(); ++i) {
    EXPECT_EQ(only_yaw.bricks[i].placement.pose.translation(),
              base.bricks[i].placement.pose.translation());
    EXPECT_EQ(only_yaw.bricks[i].placement.pose.linear(), a.bricks[i].placement.pose.linear());
  }
}

TEST(PoseNoise, BadBoundsSeedsAndKeysAreRefusedNamingThem) {
  const std::string bricks = "bricks: [{id: a, position: [0, 0, 0.0039]}]\n";
  expectRefused(bricks + "pose_noise: {position: .nan}\n", {"pose_noise.position", "finite"});
  expectRefused(bricks + "pose_noise: {position: -0.001}\n", {"pose_noise.position", "[0, 0.1]"});
  expectRefused(bricks + "pose_noise: {position: 0.2}\n", {"pose_noise.position"});
  expectRefused(bricks + "pose_noise: {yaw: -0.1}\n", {"pose_noise.yaw", "[0, pi]"});
  expectRefused(bricks + "pose_noise: {yaw: 4}\n", {"pose_noise.yaw"});
  expectRefused(bricks + "pose_noise: {yaw: .inf}\n", {"pose_noise.yaw", "finite"});
  expectRefused(bricks + "pose_noise: {seed: -3}\n", {"pose_noise.seed", ">= 0"});
  expectRefused(bricks + "pose_noise: {seed: 2.5}\n", {"pose_noise.seed", "integer"});
  expectRefused(bricks + "pose_noise: {position: 0.001, sead: 1}\n",
                {"pose_noise", "unknown key 'sead'"});
  expectRefused(bricks + "pose_noise: 0.001\n", {"pose_noise", "expected a map"});
}

TEST(SceneFriction, IsReadCheckedAndGivenToEveryTypeAndTheTable) {
  const Scene scene = parsed(
      "friction: 0.25\n"
      "types: {plank: {size: [0.1, 0.02, 0.01], mass: 0.012, friction: 0.9}}\n"
      "bricks: [{id: a, type: plank, position: [0, 0, 0.005]}]\n");
  ASSERT_TRUE(scene.friction.has_value());
  EXPECT_EQ(*scene.friction, 0.25);
  BrickTypeLibrary types = test::packageTypes();
  ASSERT_TRUE(mergeSceneTypes(scene, &types).ok);
  for (const std::string& name : types.names()) EXPECT_EQ(types.find(name)->friction, 0.25) << name;
  WorldOptions world;
  world.table.size = Eigen::Vector2d(2.0, 1.0);
  const WorldOptions options = sceneWorldOptions(scene, world);
  EXPECT_EQ(options.table.friction, 0.25);
  EXPECT_EQ(options.table.size, Eigen::Vector2d(2.0, 1.0));  // the rest of the table as it was
  // Over a table the scene gives too.
  const Scene with_table = parsed("friction: 0\ntable: {friction: 0.7, height: 0.5}\n");
  EXPECT_EQ(sceneWorldOptions(with_table, world).table.friction, 0.0);
  EXPECT_EQ(sceneWorldOptions(with_table, world).table.height, 0.5);
  // Without it, nothing changes.
  const Scene plain = parsed("bricks: []\n");
  EXPECT_FALSE(plain.friction.has_value());
  EXPECT_EQ(sceneWorldOptions(plain, world).table.friction, world.table.friction);

  expectRefused("friction: -0.1\n", {"friction", ">= 0"});
  expectRefused("friction: .nan\n", {"friction", "finite"});
  expectRefused("friction: .inf\n", {"friction", "finite"});
  expectRefused("friction: rough\n", {"friction", "expected a number"});
  expectRefused("frictoin: 0.3\n", {"unknown key 'frictoin'"});
}

}  // namespace
}  // namespace brick_stack_sim
