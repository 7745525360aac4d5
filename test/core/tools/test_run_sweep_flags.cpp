// The flags of stack_sim_run that parameter sweeps use: --statics and
// --fall-distance, parsed and run for real.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "brick_stack_sim/tools/run_command_line.h"

namespace brick_stack_sim {
namespace {

TEST(RunSweepFlags, StaticsAndFallDistanceAreParsedWithTheirDefaults) {
  RunCommandLine plain;
  ASSERT_TRUE(parseRunCommandLine({"--scene", "x"}, "/pkg", &plain).ok);
  EXPECT_FALSE(plain.statics);
  EXPECT_EQ(plain.fall_distance, 0.01);
  RunCommandLine cli;
  const Status s =
      parseRunCommandLine({"--statics", "--scene", "x", "--fall-distance", "0.025"}, "/pkg", &cli);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_TRUE(cli.statics);
  EXPECT_EQ(cli.fall_distance, 0.025);
  const std::string usage = runUsage();
  EXPECT_NE(usage.find("--statics"), std::string::npos);
  EXPECT_NE(usage.find("--fall-distance D"), std::string::npos);
}

TEST(RunSweepFlags, BadFallDistancesAreNamed) {
  struct Case {
    std::vector<std::string> args;
    const char* expected;
  };
  const Case cases[] = {
      {{"--scene", "x", "--fall-distance"}, "--fall-distance needs a value"},
      {{"--scene", "x", "--fall-distance", "0"}, "--fall-distance must be > 0 m"},
      {{"--scene", "x", "--fall-distance", "-0.01"}, "--fall-distance must be > 0 m"},
      {{"--scene", "x", "--fall-distance", "nan"}, "--fall-distance expects a finite number"},
      {{"--scene", "x", "--fall-distance", "inf"}, "--fall-distance expects a finite number"},
      {{"--scene", "x", "--fall-distance", "1cm"}, "--fall-distance expects a finite number"},
      {{"--scene", "x", "--fall-angle", "0"}, "--fall-angle must be > 0 rad"},
      {{"--scene", "x", "--fall-angle", "nan"}, "--fall-angle expects a finite number"},
      {{"--scene", "x", "--statics", "yes"}, "unexpected argument 'yes'"},
  };
  for (const Case& c : cases) {
    RunCommandLine cli;
    const Status s = parseRunCommandLine(c.args, "/pkg", &cli);
    EXPECT_FALSE(s.ok) << c.expected;
    EXPECT_NE(s.message.find(c.expected), std::string::npos) << s.message;
  }
}

/// Runs the real executable; its report (standard output) into `report`;
/// returns the exit code.
int runForReport(const std::string& args, std::string* report) {
  const std::string command = std::string(STACK_SIM_RUN_PATH) + " " + args + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buffer[4096];
  report->clear();
  while (std::fgets(buffer, sizeof buffer, pipe)) *report += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(RunSweepFlags, TheRunnerWritesTheLabelOnlyWhenAskedAndTheFallKeysAlways) {
  const std::string scene = ::testing::TempDir() + "/sweep_block_tower.yaml";
  std::ofstream(scene) << "generator: {name: block_tower, type: cube, bricks: 4, "
                          "criticality: 1.2, seed: 9}\n";
  std::string report;
  ASSERT_EQ(runForReport("--scene " + scene + " --duration 1", &report), 0);
  EXPECT_EQ(report.find("\"statics\""), std::string::npos) << report;
  EXPECT_NE(report.find("\"fall_distance\": 0.01,"), std::string::npos) << report;
  EXPECT_NE(report.find("\"first_fall_t\": "), std::string::npos) << report;
  EXPECT_EQ(report.find("\"fallen\": 0,"), std::string::npos) << report;  // it topples
  ASSERT_EQ(
      runForReport("--scene " + scene + " --duration 1 --statics --fall-distance 0.5", &report), 0);
  EXPECT_NE(report.find("\"statics\": {\"stands\": false, \"margin\": "), std::string::npos)
      << report;
  EXPECT_NE(report.find(", \"bricks\": 4}"), std::string::npos) << report;
  EXPECT_NE(report.find("\"fall_distance\": 0.5,"), std::string::npos) << report;
  std::remove(scene.c_str());
}

}  // namespace
}  // namespace brick_stack_sim
