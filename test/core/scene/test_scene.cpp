#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/generators.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaThickness;
using test::kKaplaWidth;

TEST(Scene, ParsesBricksWithTimesAndPoses) {
  Scene scene;
  const Status s = parseScene(R"(
bricks:
  - {id: b1, at: 1.0, position: [0.01, 0, 0.0117], rpy: [0, 0, 1.5708],
     linear_velocity: [0, 0, -0.1], angular_velocity: [0, 0, 0]}
  - {id: b0, type: kapla, at: 0.0, position: [0, 0, 0.0039], rpy: [0, 0, 0]}
)",
                              "two", test::packageTypes(), &scene);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_EQ(scene.name, "two");
  ASSERT_EQ(scene.bricks.size(), 2u);
  EXPECT_EQ(scene.bricks[0].placement.id, "b0");  // sorted by placement time
  EXPECT_EQ(scene.bricks[1].at, 1.0);
  const BrickPlacement& b1 = scene.bricks[1].placement;
  EXPECT_NEAR(b1.pose.translation().z(), 0.0117, 1e-15);
  // yaw 1.5708 turns the brick's long x axis onto y.
  EXPECT_NEAR(b1.pose.linear().col(0).y(), 1.0, 1e-8);
  EXPECT_DOUBLE_EQ(b1.linear_velocity.z(), -0.1);
}

TEST(Scene, RefusesTyposAndBadValuesWithTheirPlace) {
  const BrickTypeLibrary types = test::packageTypes();
  Scene scene;
  Status s = parseScene("bricks:\n  - {positon: [0, 0, 0.0039]}\n", "typo", types, &scene);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("positon"), std::string::npos) << s.message;
  s = parseScene("bricks:\n  - {position: [0, 0]}\n", "short", types, &scene);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("bricks[0].position"), std::string::npos) << s.message;
  s = parseScene("bricks:\n  - {position: [0, .nan, 0]}\n", "nan", types, &scene);
  EXPECT_FALSE(s.ok);
  s = parseScene("bricks:\n  - {id: a, position: [0, 0, 0.01]}\n  - {id: a, position: [0, 1, 0]}\n",
                 "dup", types, &scene);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("twice"), std::string::npos) << s.message;
  s = parseScene("bricks:\n  - {type: marble, position: [0, 0, 0.01]}\n", "type", types, &scene);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("marble"), std::string::npos) << s.message;
  s = parseScene("generator: {name: spiral}\n", "gen", types, &scene);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("spiral"), std::string::npos) << s.message;
  s = parseScene("bricks: [\n", "broken", types, &scene);
  EXPECT_FALSE(s.ok);
  s = parseScene("types: {slab: {size: [0.1, 0, 0.01], mass: 0.1}}\n", "zero", types, &scene);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("size"), std::string::npos) << s.message;
}

TEST(Scene, UnknownSceneNameSaysWhereItLooked) {
  Scene scene;
  const Status s =
      loadScene("no_such_scene", {test::dataPath("scenes")}, test::packageTypes(), &scene);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("no_such_scene"), std::string::npos);
  EXPECT_NE(s.message.find("scenes"), std::string::npos);
}

TEST(Scene, SceneTypesAndTableAreRead) {
  Scene scene;
  const Status s = parseScene(R"(
table: {size: [0.5, 0.4], friction: 0.7}
types: {slab: {size: [0.1, 0.1, 0.01], mass: 0.06}}
bricks: [{type: slab, position: [0, 0, 0.005]}]
)",
                              "custom", test::packageTypes(), &scene);
  ASSERT_TRUE(s.ok) << s.message;
  ASSERT_TRUE(scene.table.has_value());
  EXPECT_DOUBLE_EQ(scene.table->size.x(), 0.5);
  EXPECT_DOUBLE_EQ(scene.table->friction, 0.7);
  ASSERT_EQ(scene.types.size(), 1u);
  // Inertia of a uniform box: m (b^2 + c^2) / 12.
  EXPECT_NEAR(scene.types[0].inertia.x(), 0.06 * (0.01 + 0.0001) / 12, 1e-15);
}

TEST(Scene, TowerLayersCrossAndRestOnEachOther) {
  std::vector<ScheduledBrick> bricks;
  TowerParams params;
  params.layers = 4;
  params.interval = 1.0;
  ASSERT_TRUE(generateTower(params, test::packageTypes(), &bricks).ok);
  ASSERT_EQ(bricks.size(), 8u);
  const double offset = (kKaplaLength - kKaplaWidth) / 2;
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    const int layer = static_cast<int>(i / 2);
    const Eigen::Isometry3d& pose = bricks[i].placement.pose;
    EXPECT_DOUBLE_EQ(bricks[i].at, static_cast<double>(i));
    EXPECT_NEAR(pose.translation().z(), kKaplaThickness * (layer + 0.5), 1e-15);
    const Eigen::Vector3d long_axis = pose.linear().col(0);
    if (layer % 2 == 0) {
      EXPECT_NEAR(std::abs(long_axis.x()), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(pose.translation().y()), offset, 1e-15);
    } else {
      EXPECT_NEAR(std::abs(long_axis.y()), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(pose.translation().x()), offset, 1e-15);
    }
  }
  // The ends of a crosswise brick lie exactly over the two bricks below it.
  EXPECT_NEAR(offset + kKaplaWidth / 2, kKaplaLength / 2, 1e-15);
  // The ROS tests place the tower laid by hand in test/support/kapla.h
  // through ~place_brick: it is the generator's, brick for brick.
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    const BrickPlacement by_hand = test::towerBrick(static_cast<int>(i));
    EXPECT_TRUE(bricks[i].placement.pose.isApprox(by_hand.pose, 1e-12)) << i;
  }
}

TEST(Scene, TowerRefusesBadParameters) {
  std::vector<ScheduledBrick> bricks;
  TowerParams params;
  params.bricks_per_layer = 4;
  EXPECT_FALSE(generateTower(params, test::packageTypes(), &bricks).ok);
  params.bricks_per_layer = 3;
  params.layers = 0;
  EXPECT_FALSE(generateTower(params, test::packageTypes(), &bricks).ok);
  params.layers = 2;
  params.type = "marble";
  EXPECT_FALSE(generateTower(params, test::packageTypes(), &bricks).ok);
  params.type = "";
  params.layers = 5000;  // 5000 x 3 x 100 towers: 1.5 million bricks
  params.grid_x = params.grid_y = 10;
  const Status huge = generateTower(params, test::packageTypes(), &bricks);
  EXPECT_FALSE(huge.ok);
  EXPECT_NE(huge.message.find("100000"), std::string::npos) << huge.message;
  EXPECT_TRUE(bricks.empty());
}

TEST(Scene, AFrameIsTwoMirroredPlanksMeetingAtTheApex) {
  AFrameParams params;
  params.angle = 0.349;
  params.origin = Eigen::Vector2d(0.1, -0.05);
  std::vector<ScheduledBrick> bricks;
  ASSERT_TRUE(generateAFrame(params, test::packageTypes(), &bricks).ok);
  ASSERT_EQ(bricks.size(), 2u);
  const Eigen::Isometry3d& left = bricks[0].placement.pose;
  const Eigen::Isometry3d& right = bricks[1].placement.pose;
  // Each length axis leans by the angle from vertical, towards the other.
  EXPECT_NEAR(std::acos(left.linear().col(0).cwiseAbs().z()), params.angle, 1e-12);
  EXPECT_NEAR(std::acos(right.linear().col(0).cwiseAbs().z()), params.angle, 1e-12);
  EXPECT_NEAR(left.translation().x() + right.translation().x(), 2 * 0.1, 1e-12);
  EXPECT_NEAR(left.translation().y(), -0.05, 1e-12);
  // The centre of a plank on its inner foot edge: (L cos + T sin) / 2 up.
  const double a = params.angle;
  EXPECT_NEAR(left.translation().z(),
              0.5 * (kKaplaLength * std::cos(a) + kKaplaThickness * std::sin(a)), 1e-12);
  EXPECT_EQ(bricks[0].at, bricks[1].at);  // a V is placed whole or not at all
}

TEST(Scene, CardHouseHasItsRowsAndRefusesWhatCannotStand) {
  CardHouseParams params;
  params.levels = 3;
  params.interval = 0.5;
  std::vector<ScheduledBrick> bricks;
  ASSERT_TRUE(generateCardHouse(params, test::packageTypes(), &bricks).ok);
  // 3 + 2 + 1 V's of two planks, 2 + 1 level planks.
  ASSERT_EQ(bricks.size(), 15u);
  // Both planks of a V at one time: V's and level planks alternate in time.
  EXPECT_EQ(bricks[0].at, bricks[1].at);
  EXPECT_EQ(bricks[6].at - bricks[5].at, 0.5);
  for (const ScheduledBrick& b : bricks) EXPECT_GE(b.placement.pose.translation().z(), 0.0);
  for (const double angle : {0.0, -0.1, 2.0, std::nan("")}) {
    params.angle = angle;
    EXPECT_FALSE(generateCardHouse(params, test::packageTypes(), &bricks).ok) << angle;
  }
  // At 40 degrees a V is wider than a level plank: one level only.
  params.angle = 40.0 * M_PI / 180.0;
  const Status wide = generateCardHouse(params, test::packageTypes(), &bricks);
  EXPECT_FALSE(wide.ok);
  EXPECT_NE(wide.message.find("levels: 1"), std::string::npos) << wide.message;
  params.levels = 1;
  EXPECT_TRUE(generateCardHouse(params, test::packageTypes(), &bricks).ok);
  params.levels = 0;
  EXPECT_FALSE(generateCardHouse(params, test::packageTypes(), &bricks).ok);
}

TEST(Scene, PackageScenesAllLoad) {
  int scenes = 0;
  for (const auto& file : std::filesystem::directory_iterator(test::dataPath("scenes"))) {
    if (file.path().extension() != ".yaml") continue;
    ++scenes;
    Scene scene;
    const Status s = loadScene(file.path().string(), {}, test::packageTypes(), &scene);
    EXPECT_TRUE(s.ok) << s.message;
    EXPECT_EQ(scene.bricks.empty(), file.path().stem() == "empty") << file.path();
    EXPECT_EQ(scene.name, file.path().stem().string()) << "a scene is named after its file";
  }
  // The six demos (README.md, "Demos: the thesis's experiments") and the
  // benchmark's scenes.
  EXPECT_GE(scenes, 20);
}

/// A scene file that is not one: refused at once, with what it is.
TEST(Scene, OnlyRegularFilesWithinTheSizeLimitAreRead) {
  const BrickTypeLibrary types = test::packageTypes();
  Scene scene;
  const std::string dir = ::testing::TempDir() + "/scene_files";
  std::filesystem::create_directories(dir);
  const std::string fifo = dir + "/fifo.yaml";
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string sparse = dir + "/sparse.yaml";
  { std::ofstream file(sparse); }
  std::filesystem::resize_file(sparse, 1ull << 30);  // 1 GiB of holes, written in no time
  const std::pair<std::string, std::string> cases[] = {
      {"/dev/zero", "not a regular file"},
      {fifo, "not a regular file"},
      {dir, "is a directory"},
      {sparse, "1073741824 bytes, more than the limit of 67108864"},
  };
  for (const auto& [path, expected] : cases) {
    const Status s = loadScene(path, {}, types, &scene);
    EXPECT_FALSE(s.ok) << path;
    EXPECT_NE(s.message.find(expected), std::string::npos) << s.message;
  }
  // By name too: a FIFO in a scene directory does not block the lookup.
  EXPECT_NE(loadScene("fifo", {dir}, types, &scene).message.find("not a regular file"),
            std::string::npos);
  // The limit is the caller's.
  const std::string small = dir + "/small.yaml";
  {
    std::ofstream file(small);
    file << "bricks:\n  - {position: [0, 0, 0.0039]}\n" << std::string(2000, '#') << "\n";
  }
  EXPECT_FALSE(loadScene(small, {}, types, &scene, SceneLimits{1024}).ok);
  EXPECT_TRUE(loadScene(small, {}, types, &scene, SceneLimits{4096}).ok);
  std::filesystem::remove_all(dir);
}

TEST(Scene, PlacementTimesHaveALimit) {
  const BrickTypeLibrary types = test::packageTypes();
  Scene scene;
  const Status late =
      parseScene("bricks:\n  - {at: 1e7, position: [0, 0, 0.0039]}", "s", types, &scene);
  EXPECT_FALSE(late.ok);
  EXPECT_NE(late.message.find("bricks[0].at"), std::string::npos) << late.message;
  const Status generated =
      parseScene("generator: {name: tower, layers: 3, interval: 400000}", "s", types, &scene);
  EXPECT_FALSE(generated.ok);
  // The fourth brick is the first too late: 3 intervals of 4e5 s.
  EXPECT_NE(generated.message.find("brick 'b3' is placed at 1.2e+06 s, after the latest allowed "
                                   "1000000 s"),
            std::string::npos)
      << generated.message;
  EXPECT_TRUE(
      parseScene("bricks:\n  - {at: 1e6, position: [0, 0, 0.0039]}", "s", types, &scene).ok);
}

TEST(Scene, ExpectedOutcomeIsReadAndCheckedAndStandsByDefault) {
  Scene scene;
  ASSERT_TRUE(parseScene("bricks: []", "s", test::packageTypes(), &scene).ok);
  EXPECT_EQ(scene.expect, ExpectedOutcome::kStands);
  ASSERT_TRUE(parseScene("expect: collapses\nbricks: []", "s", test::packageTypes(), &scene).ok);
  EXPECT_EQ(scene.expect, ExpectedOutcome::kCollapses);
  const Status typo = parseScene("expect: falls", "s", test::packageTypes(), &scene);
  EXPECT_FALSE(typo.ok);
  EXPECT_NE(typo.message.find("'stands' or 'collapses'"), std::string::npos) << typo.message;
}

TEST(Scene, ImpactThrowsABrickSquareAtTheOuterFaceOfTheStruckLayer) {
  for (int layer : {3, 4, 13}) {
    ImpactParams params;
    params.tower.layers = 13;
    params.tower.interval = 0.25;
    params.layer = layer;
    params.speed = 2.0;
    std::vector<ScheduledBrick> bricks;
    ASSERT_TRUE(generateImpact(params, test::packageTypes(), &bricks).ok);
    ASSERT_EQ(bricks.size(), 27u);
    const ScheduledBrick& striker = bricks.back();
    EXPECT_EQ(striker.placement.id, kStrikerId);
    // Thrown 1 s after the last tower brick (26 bricks, 0.25 s apart).
    EXPECT_DOUBLE_EQ(striker.at, 25 * 0.25 + 1.0);
    // The first brick of the layer: even layers (from 0) at y = -offset
    // along x, struck from -y; odd ones at x = -offset along y, from -x.
    const test::TowerSlot slot = test::towerSlot(layer - 1, 0);
    const bool along_x = (layer - 1) % 2 == 0;
    const Eigen::Vector3d inward = along_x ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
    EXPECT_TRUE(striker.placement.linear_velocity.isApprox(2.0 * inward)) << layer;
    const Eigen::Vector3d centre = striker.placement.pose.translation();
    EXPECT_NEAR(centre.z(), slot.z + kImpactAimAbove, 1e-12) << "aimed at the layer";
    const double face = (along_x ? slot.y : slot.x) - kKaplaWidth / 2;
    const double striker_front = (along_x ? centre.y() : centre.x()) + kKaplaWidth / 2;
    // 4 mm away at most, and no further than 2 ms of flight at 2 m/s.
    EXPECT_NEAR(face - striker_front, 2.0 * kMaxImpactFlight, 1e-12) << layer;
    // Parallel to the brick it strikes, over its middle.
    EXPECT_NEAR(along_x ? centre.x() : centre.y(), 0.0, 1e-12);
    const Eigen::Vector3d long_axis = striker.placement.pose.linear() * Eigen::Vector3d::UnitX();
    EXPECT_NEAR(
        std::abs(long_axis.dot(along_x ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())), 1.0,
        1e-12);
  }
}

TEST(Scene, ImpactRefusesALayerOutsideTheTowerAndAnUnphysicalSpeed) {
  ImpactParams params;
  params.tower.layers = 5;
  std::vector<ScheduledBrick> bricks;
  for (int layer : {0, 6}) {
    params.layer = layer;
    const Status s = generateImpact(params, test::packageTypes(), &bricks);
    EXPECT_FALSE(s.ok) << layer;
    EXPECT_NE(s.message.find("[1, 5]"), std::string::npos) << s.message;
  }
  params.layer = 5;
  for (double speed : {0.0, -1.0, std::nan(""), 1e9}) {
    params.speed = speed;
    EXPECT_FALSE(generateImpact(params, test::packageTypes(), &bricks).ok) << speed;
  }
  EXPECT_TRUE(bricks.empty()) << "a refused generator appends nothing";
}

TEST(Scene, KaplaRecordIsFloorsOfTwoCrossedLayers) {
  Scene scene;
  ASSERT_TRUE(
      loadScene("kapla_record", {test::dataPath("scenes")}, test::packageTypes(), &scene).ok);
  ASSERT_EQ(scene.bricks.size(), 133u * 4u);
  double top = 0.0;
  for (const ScheduledBrick& brick : scene.bricks)
    top = std::max(top, brick.placement.pose.translation().z() + kKaplaThickness / 2);
  EXPECT_NEAR(top, 266 * kKaplaThickness, 1e-9);
  KaplaRecordParams params;
  params.floors = 0;
  std::vector<ScheduledBrick> bricks;
  EXPECT_FALSE(generateKaplaRecord(params, test::packageTypes(), &bricks).ok);
}

}  // namespace
}  // namespace brick_stack_sim
