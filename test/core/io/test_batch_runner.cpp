#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

Scene loadPackageScene(const std::string& name) {
  Scene scene;
  const Status s = loadScene(name, {test::dataPath("scenes")}, test::packageTypes(), &scene);
  EXPECT_TRUE(s.ok) << s.message;
  return scene;
}

/// The report without its wall-clock entries, which no two runs share.
std::string withoutWallTime(std::string json) {
  std::size_t start = json.find("\"wall_time\": ");
  json.erase(start, json.find(',', start) - start);
  for (const char* key : {"\"stage_seconds\": ", "\"bullet_stages\": "}) {
    start = json.find(key);
    json.erase(start, json.find('}', start) + 1 - start);
  }
  return json;
}

TEST(BatchRunner, ReportHasTheContractKeys) {
  RunOptions options;
  options.world.stability.mode = "none";  // a brick in plain Bullet: dynamic, awake every step
  options.duration = 0.2;
  RunReport report;
  ASSERT_TRUE(runScene(loadPackageScene("single_drop"), test::packageTypes(), options, &report).ok);
  const std::string json = toJson(report);
  for (const char* key : {"\"scene\": \"single_drop\"",
                          "\"mode\": \"none\"",
                          "\"time_step\": ",
                          "\"iterations\": 20",
                          "\"sim_time\": ",
                          "\"wall_time\": ",
                          "\"steps\": 200",
                          "\"nonfinite\": 0",
                          "\"lost\": 0",
                          "\"missing\": 0",
                          "\"cost\": {\"bullet_steps\": 200, \"awake_brick_steps\": 200",
                          "\"stage_seconds\": {",
                          "\"bullet_stages\": {\"broadphase\": ",
                          "\"bricks\": [",
                          "\"id\": \"b0\"",
                          "\"type\": \"kapla\"",
                          "\"placed_at\": 0",
                          "\"position\": [",
                          "\"orientation\": [",
                          "\"state\": \"dynamic\"",
                          "\"linear_velocity\": [",
                          "\"angular_velocity\": [",
                          "\"displacement\": ",
                          "\"rotation\": ",
                          "\"events\": [",
                          "\"kind\": \"spawned\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << "missing " << key << " in " << json;
  }
  EXPECT_NEAR(report.sim_time, 0.2, 1e-12);
}

TEST(BatchRunner, PlacesBricksAtTheirTimes) {
  Scene scene = loadPackageScene("tower25_built");
  RunOptions options;
  options.duration = 3.0;
  RunReport report;
  ASSERT_TRUE(runScene(scene, test::packageTypes(), options, &report).ok);
  ASSERT_EQ(report.bricks.size(), 4u);  // at 0, 1, 2 and 3 s
  EXPECT_NEAR(report.bricks[3].brick.placed_at, 3.0, 0.5e-3);
  EXPECT_TRUE(report.refused.empty());
}

TEST(BatchRunner, SameSceneTwiceGivesTheSameReport) {
  Scene scene = loadPackageScene("tower10");
  RunOptions options;
  options.duration = 1.0;
  options.world.sleeping.enabled = false;
  RunReport first, second;
  ASSERT_TRUE(runScene(scene, test::packageTypes(), options, &first).ok);
  ASSERT_TRUE(runScene(scene, test::packageTypes(), options, &second).ok);
  EXPECT_EQ(withoutWallTime(toJson(first)), withoutWallTime(toJson(second)));
}

TEST(BatchRunner, RefusedPlacementIsReportedNotLost) {
  Scene scene;
  ASSERT_TRUE(parseScene("bricks:\n"
                         "  - {id: a, at: 0.0, position: [0, 0, 0.0039]}\n"
                         "  - {id: b, at: 0.1, position: [0.01, 0, 0.0039]}\n",
                         "clash", test::packageTypes(), &scene)
                  .ok);
  RunOptions options;
  options.duration = 0.2;
  RunReport report;
  ASSERT_TRUE(runScene(scene, test::packageTypes(), options, &report).ok);
  ASSERT_EQ(report.refused.size(), 1u);
  EXPECT_EQ(report.refused[0].id, "b");
  EXPECT_NE(report.refused[0].reason.find("overlaps brick 'a'"), std::string::npos);
  EXPECT_NE(toJson(report).find("\"refused\": [{"), std::string::npos);
  EXPECT_EQ(report.lost(), 0u);
  EXPECT_EQ(report.missing(), 0u);
}

TEST(BatchRunner, ABrickThatLeavesTheWorldIsCountedLostNotMissing) {
  Scene scene;
  ASSERT_TRUE(
      parseScene("bricks:\n"
                 "  - {id: a, at: 0.0, position: [0, 0, 0.0039]}\n"
                 "  - {id: up, at: 0.0, position: [0.3, 0, 0.5], linear_velocity: [0, 0, 20]}\n",
                 "throw", test::packageTypes(), &scene)
          .ok);
  RunOptions options;
  options.world.bounds.height = 2.0;
  options.duration = 0.3;
  RunReport report;
  ASSERT_TRUE(runScene(scene, test::packageTypes(), options, &report).ok);
  EXPECT_EQ(report.bricks.size(), 1u);
  EXPECT_EQ(report.lost(), 1u);
  EXPECT_EQ(report.missing(), 0u);
  const std::string json = toJson(report);
  EXPECT_NE(json.find("\"lost\": 1"), std::string::npos);
  EXPECT_NE(json.find("\"kind\": \"lost\""), std::string::npos);
}

}  // namespace
}  // namespace brick_stack_sim
