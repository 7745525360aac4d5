#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/tools/run_command_line.h"
#include "test_support.h"

namespace brick_stack_sim {
namespace {

Scene loadPackageScene(const std::string& name) {
  Scene scene;
  const Status s = loadScene(name, {test::dataPath("scenes")}, test::packageTypes(), &scene);
  EXPECT_TRUE(s.ok) << s.message;
  return scene;
}

/// The report without its two wall-clock entries, which no two runs share.
std::string withoutWallTime(std::string json) {
  std::size_t start = json.find("\"wall_time\": ");
  json.erase(start, json.find(',', start) - start);
  start = json.find("\"stage_seconds\": ");
  return json.erase(start, json.find('}', start) + 1 - start);
}

TEST(BatchRunner, ReportHasTheContractKeys) {
  RunOptions options;
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
                          "\"cost\": {\"bullet_steps\": 200, \"awake_brick_steps\": 200",
                          "\"stage_seconds\": {",
                          "\"bricks\": [",
                          "\"id\": \"b0\"",
                          "\"type\": \"kapla\"",
                          "\"placed_at\": 0",
                          "\"position\": [",
                          "\"orientation\": [",
                          "\"state\": \"dynamic\"",
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
  options.world.sleeping = false;
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
}

TEST(RunCommandLine, ParsesTheDocumentedFlags) {
  RunCommandLine cli;
  const Status s = parseRunCommandLine(
      {"--scene", "tower10", "--mode", "none", "--duration", "20", "--time-step", "0.002",
       "--iterations", "30", "--no-sleep", "--report", "out.json"},
      "/pkg", &cli);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_EQ(cli.scene, "tower10");
  EXPECT_DOUBLE_EQ(*cli.duration, 20.0);
  EXPECT_DOUBLE_EQ(cli.world.time_step, 0.002);
  EXPECT_EQ(cli.world.solver_iterations, 30);
  EXPECT_FALSE(cli.world.sleeping);
  EXPECT_EQ(cli.report_path, "out.json");
  EXPECT_EQ(cli.types_urdf, "/pkg/urdf/bricks.urdf");
  EXPECT_EQ(cli.scene_dirs, std::vector<std::string>{"/pkg/scenes"});
}

TEST(RunCommandLine, BadFlagsAreNamed) {
  struct Case {
    std::vector<std::string> args;
    const char* expected;
  };
  const Case cases[] = {
      {{"--scene", "x", "--bogus"}, "--bogus"},
      {{"--scene", "x", "--time-step"}, "--time-step needs a value"},
      {{"--scene", "x", "--time-step", "fast"}, "--time-step"},
      {{"--scene", "x", "--time-step", "nan"}, "--time-step"},
      {{"--scene", "x", "--time-step", "-1"}, "time_step"},
      {{"--scene", "x", "--iterations", "2.5"}, "--iterations"},
      {{"--scene", "x", "--iterations", "0"}, "solver_iterations"},
      {{"--scene", "x", "--mode", "magic"}, "magic"},
      {{"--scene", "x", "--mode", "equilibrium"}, "not available"},
      {{"--scene", "x", "--duration", "-3"}, "--duration"},
      {{"--mode", "none"}, "--scene is required"},
      {{"tower10"}, "unexpected argument"},
  };
  for (const Case& c : cases) {
    RunCommandLine cli;
    const Status s = parseRunCommandLine(c.args, "/pkg", &cli);
    EXPECT_FALSE(s.ok) << c.expected;
    EXPECT_NE(s.message.find(c.expected), std::string::npos) << s.message;
  }
}

/// Runs the real executable; returns its exit code and fills `output` with stderr.
int runExecutable(const std::string& args, std::string* output) {
  const std::string command = std::string(STACK_SIM_RUN_PATH) + " " + args + " 2>&1 >/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buffer[512];
  output->clear();
  while (std::fgets(buffer, sizeof buffer, pipe)) *output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(StackSimRun, WritesTheReportAndFailsClearlyOnBadInput) {
  const std::string report_path = ::testing::TempDir() + "/stack_sim_run_report.json";
  std::remove(report_path.c_str());
  std::string output;
  ASSERT_EQ(runExecutable("--scene single_drop --duration 0.5 --report " + report_path, &output), 0)
      << output;
  std::ifstream report(report_path);
  std::stringstream text;
  text << report.rdbuf();
  EXPECT_NE(text.str().find("\"scene\": \"single_drop\""), std::string::npos);
  EXPECT_NE(output.find("largest displacement"), std::string::npos) << output;

  EXPECT_NE(runExecutable("--scene no_such_scene", &output), 0);
  EXPECT_NE(output.find("unknown scene 'no_such_scene'"), std::string::npos) << output;
  EXPECT_NE(runExecutable("--scene single_drop --frobnicate", &output), 0);
  EXPECT_NE(output.find("--frobnicate"), std::string::npos) << output;
}

}  // namespace
}  // namespace brick_stack_sim
