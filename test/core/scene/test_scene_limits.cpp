// The limits of a scene (docs/ros_interface.md, "Refusals and limits"):
// scene_max_bricks counted from the generators' parameters before any brick
// is built, and messages that never echo a huge name or path back.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/generators.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

/// `count` tower generators of `layers` layers of two bricks each.
std::string towers(int count, int layers) {
  std::ostringstream yaml;
  yaml << "generator:\n";
  for (int i = 0; i < count; ++i)
    yaml << "  - {name: tower, layers: " << layers << ", origin: [" << 0.2 * i << ", 0]}\n";
  return yaml.str();
}

SceneLimits bricksAtMost(int max_bricks) {
  SceneLimits limits;
  limits.max_bricks = max_bricks;
  return limits;
}

TEST(SceneLimits, TheDefaultIsOneGeneratorsLargest) {
  EXPECT_EQ(SceneLimits().max_bricks, 100000);
  EXPECT_EQ(SceneLimits().max_bytes, 64 << 20);
}

TEST(SceneLimits, ManyGeneratorsAreRefusedAtTheOneThatPassesTheCap) {
  // 50 towers of 10 bricks: the 3rd brings the scene to 30 of at most 25.
  Scene scene;
  scene.name = "untouched";
  const Status s =
      parseScene(towers(50, 5), "many", test::packageTypes(), &scene, bricksAtMost(25));
  ASSERT_FALSE(s.ok);
  EXPECT_NE(s.message.find("generator 3 (tower) would bring the scene to 30 bricks: at most 25 "
                           "(scene_max_bricks)"),
            std::string::npos)
      << s.message;
  EXPECT_EQ(scene.name, "untouched");
  EXPECT_TRUE(scene.bricks.empty());
}

TEST(SceneLimits, TheCountComesBeforeAnyGeneratorIsBuilt) {
  // The first generator would be refused when built (no such type): the
  // count of the second is what the scene is refused for, so nothing was built.
  const std::string yaml =
      "generator:\n"
      "  - {name: tower, layers: 2, type: marble}\n"
      "  - {name: pile, bricks: 100}\n";
  Scene scene;
  const Status s = parseScene(yaml, "s", test::packageTypes(), &scene, bricksAtMost(50));
  ASSERT_FALSE(s.ok);
  EXPECT_NE(s.message.find("generator 2 (pile) would bring the scene to 104 bricks"),
            std::string::npos)
      << s.message;
  EXPECT_EQ(s.message.find("marble"), std::string::npos) << s.message;
}

TEST(SceneLimits, AHugeGeneratorIsCountedNotBuilt) {
  // 50 generators of 100 000 bricks each in a few kilobytes: refused at the
  // second with the default cap, before a brick is built.
  std::ostringstream yaml;
  yaml << "generator:\n";
  for (int i = 0; i < 50; ++i)
    yaml << "  - {name: tower, layers: 10000, bricks_per_layer: 2, grid: [5, 1]}\n";
  ASSERT_LT(yaml.str().size(), 4096u);
  Scene scene;
  const Status s = parseScene(yaml.str(), "huge", test::packageTypes(), &scene);
  ASSERT_FALSE(s.ok);
  EXPECT_NE(s.message.find("generator 2 (tower) would bring the scene to 200000 bricks: at most "
                           "100000 (scene_max_bricks)"),
            std::string::npos)
      << s.message;
  // Parameters whose product overflows an int are counted, not wrapped round.
  const Status card = parseScene("generator: {name: card_house, levels: 2000000000}", "c",
                                 test::packageTypes(), &scene);
  ASSERT_FALSE(card.ok);
  EXPECT_NE(card.message.find("generator 1 (card_house) would bring the scene to"),
            std::string::npos)
      << card.message;
}

TEST(SceneLimits, ASceneOfExactlyTheCapIsAccepted) {
  // 10 (tower) + 6 (pyramid of 3) + 2 (aframe) + 2 listed = 20.
  const std::string yaml =
      "generator:\n"
      "  - {name: tower, layers: 5}\n"
      "  - {name: pyramid, base: 3, origin_unused: 0}\n";
  Scene scene;
  // An unknown key is still the generator's own error, not the count's.
  EXPECT_NE(parseScene(yaml, "s", test::packageTypes(), &scene, bricksAtMost(20))
                .message.find("origin_unused"),
            std::string::npos);
  const std::string exact =
      "generator:\n"
      "  - {name: tower, layers: 5}\n"
      "  - {name: pyramid, base: 3}\n"
      "  - {name: aframe, origin: [0.3, 0.3]}\n"
      "bricks:\n"
      "  - {id: x, position: [-0.3, 0, 0.0039]}\n"
      "  - {id: y, position: [-0.3, 0.2, 0.0039]}\n";
  const Status at_cap = parseScene(exact, "s", test::packageTypes(), &scene, bricksAtMost(20));
  ASSERT_TRUE(at_cap.ok) << at_cap.message;
  EXPECT_EQ(scene.bricks.size(), 20u);
  // One fewer allowed: the listed bricks are what passes it.
  const Status over = parseScene(exact, "s", test::packageTypes(), &scene, bricksAtMost(19));
  ASSERT_FALSE(over.ok);
  EXPECT_NE(over.message.find("the list of 2 would bring the scene to 20 bricks: at most 19"),
            std::string::npos)
      << over.message;
  EXPECT_EQ(scene.bricks.size(), 20u);  // the refusal left the last scene as it was
}

TEST(SceneLimits, EveryGeneratorCountsWhatItBuilds) {
  const BrickTypeLibrary types = test::packageTypes();
  auto built = [](const Status& status, const std::vector<ScheduledBrick>& bricks) {
    EXPECT_TRUE(status.ok) << status.message;
    return static_cast<std::int64_t>(bricks.size());
  };
  std::vector<ScheduledBrick> bricks;
  TowerParams tower;
  tower.layers = 7;
  tower.bricks_per_layer = 3;
  tower.grid_x = 2;
  tower.grid_y = 3;
  EXPECT_EQ(brickCount(tower), built(generateTower(tower, types, &bricks), bricks));
  bricks.clear();
  HarmonicParams harmonic;
  EXPECT_EQ(brickCount(harmonic),
            built(generateHarmonic(harmonic, TableOptions(), types, &bricks), bricks));
  bricks.clear();
  SlantTowerParams slant;
  EXPECT_EQ(brickCount(slant), built(generateSlantTower(slant, types, &bricks), bricks));
  bricks.clear();
  PyramidParams pyramid;
  pyramid.base = 7;
  EXPECT_EQ(brickCount(pyramid), built(generatePyramid(pyramid, types, &bricks), bricks));
  bricks.clear();
  PileParams pile;
  pile.bricks = 37;
  EXPECT_EQ(brickCount(pile), built(generatePile(pile, types, &bricks), bricks));
  bricks.clear();
  AFrameParams aframe;
  EXPECT_EQ(brickCount(aframe), built(generateAFrame(aframe, types, &bricks), bricks));
  for (int levels : {1, 2, 4}) {
    bricks.clear();
    CardHouseParams house;
    house.levels = levels;
    house.angle = 0.3;
    EXPECT_EQ(brickCount(house), built(generateCardHouse(house, types, &bricks), bricks));
  }
  bricks.clear();
  ImpactParams impact;
  impact.tower.layers = 13;
  EXPECT_EQ(brickCount(impact), built(generateImpact(impact, types, &bricks), bricks));
  bricks.clear();
  KaplaRecordParams record;
  record.floors = 9;
  EXPECT_EQ(brickCount(record), built(generateKaplaRecord(record, types, &bricks), bricks));
  // Numbers no generator accepts still count without overflow.
  TowerParams absurd;
  absurd.layers = 2000000000;
  absurd.grid_x = absurd.grid_y = 2000000000;
  EXPECT_EQ(brickCount(absurd), kMaxCountedBricks);
  absurd.layers = -3;
  EXPECT_EQ(brickCount(absurd), 0);
}

class SceneFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "/scene_limits";
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string dir_;
};

TEST_F(SceneFiles, LoadSceneAppliesBothLimits) {
  const std::string path = dir_ + "/towers.yaml";
  std::ofstream(path) << towers(4, 5);  // 40 bricks
  Scene scene;
  const Status over = loadScene(path, {}, test::packageTypes(), &scene, bricksAtMost(39));
  ASSERT_FALSE(over.ok);
  EXPECT_NE(over.message.find("scene 'towers': generator 4 (tower) would bring the scene to 40"),
            std::string::npos)
      << over.message;
  const Status exact = loadScene(path, {}, test::packageTypes(), &scene, bricksAtMost(40));
  ASSERT_TRUE(exact.ok) << exact.message;
  EXPECT_EQ(scene.bricks.size(), 40u);
  SceneLimits small;
  small.max_bytes = 100;
  const Status bytes = loadScene(path, {}, test::packageTypes(), &scene, small);
  ASSERT_FALSE(bytes.ok);
  EXPECT_NE(bytes.message.find("more than the limit of 100 (parameter scene_max_bytes)"),
            std::string::npos)
      << bytes.message;
}

TEST_F(SceneFiles, AnUnknownSceneNamesEachDirectoryOnce) {
  Scene scene;
  const Status s =
      loadScene("no_such_scene", {dir_, dir_ + "/other", dir_}, test::packageTypes(), &scene);
  ASSERT_FALSE(s.ok);
  EXPECT_NE(s.message.find("unknown scene 'no_such_scene': no such file, and no "
                           "no_such_scene.yaml in [" +
                           dir_ + ", " + dir_ + "/other]"),
            std::string::npos)
      << s.message;
}

TEST_F(SceneFiles, AHugeSceneNameOrPathIsCutInMessages) {
  // A 10 kB name was once echoed in full by ~reset.
  const std::string name(10240, 'a');
  Scene scene;
  const Status unknown = loadScene(name, {dir_}, test::packageTypes(), &scene);
  ASSERT_FALSE(unknown.ok);
  EXPECT_LT(unknown.message.size(), 1000u) << unknown.message.size();
  EXPECT_NE(unknown.message.find("(10240 characters)"), std::string::npos) << unknown.message;
  // A long path that exists, but is no scene file.
  std::string deep = dir_;
  while (deep.size() < 600) deep += "/a_long_directory_name";
  std::filesystem::create_directories(deep);
  const Status directory = loadScene(deep, {}, test::packageTypes(), &scene);
  ASSERT_FALSE(directory.ok);
  EXPECT_NE(directory.message.find("is a directory"), std::string::npos) << directory.message;
  EXPECT_NE(directory.message.find("(" + std::to_string(deep.size()) + " characters)"),
            std::string::npos)
      << directory.message;
  EXPECT_LT(directory.message.size(), 400u) << directory.message;
}

}  // namespace
}  // namespace brick_stack_sim
