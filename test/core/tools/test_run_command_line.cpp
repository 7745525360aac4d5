// The command line of stack_sim_run, parsed and run for real.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "brick_stack_sim/tools/run_command_line.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

TEST(RunCommandLine, ParsesTheDocumentedFlags) {
  RunCommandLine cli;
  const Status s = parseRunCommandLine(
      {"--scene", "tower10", "--mode", "none", "--duration", "20", "--time-step", "0.002",
       "--iterations", "30", "--no-sleep", "--report", "out.json", "--save-scene", "end.yaml"},
      "/pkg", &cli);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_EQ(cli.config.data.scene, "tower10");
  EXPECT_DOUBLE_EQ(*cli.duration, 20.0);
  EXPECT_DOUBLE_EQ(cli.config.world.time_step, 0.002);
  EXPECT_EQ(cli.config.world.solver_iterations, 30);
  EXPECT_EQ(cli.config.world.stability.mode, "none");
  EXPECT_FALSE(cli.config.world.sleeping.enabled);
  EXPECT_EQ(cli.report_path, "out.json");
  EXPECT_EQ(cli.save_scene_path, "end.yaml");
  EXPECT_EQ(cli.config.data.types_urdf, "/pkg/urdf/bricks.urdf");
  EXPECT_EQ(cli.config.data.scene_dirs, std::vector<std::string>{"/pkg/scenes"});
}

TEST(RunCommandLine, DefaultModeIsTheNodesAndTheConfigFilesSayNothingElse) {
  // The node starts from the same SimulationConfig defaults, and its launch
  // files load config/sim.yaml and config/stability.yaml, which claim to hold
  // the built-in defaults: loading them must change no option.
  RunCommandLine bare, configured;
  ASSERT_TRUE(parseRunCommandLine({"--scene", "x"}, "/pkg", &bare).ok);
  EXPECT_EQ(bare.config.world.stability.mode, "com");
  const Status s = parseRunCommandLine({"--config", test::dataPath("config/sim.yaml"), "--config",
                                        test::dataPath("config/stability.yaml"), "--scene", "x"},
                                       "/pkg", &configured);
  ASSERT_TRUE(s.ok) << s.message;
  const WorldOptions &a = bare.config.world, &b = configured.config.world;
  EXPECT_EQ(a.stability.mode, b.stability.mode);
  EXPECT_EQ(a.time_step, b.time_step);
  EXPECT_EQ(a.solver_iterations, b.solver_iterations);
  EXPECT_EQ(a.gravity, b.gravity);
  EXPECT_EQ(a.sleeping.enabled, b.sleeping.enabled);
  EXPECT_EQ(a.sleeping.linear_threshold, b.sleeping.linear_threshold);
  EXPECT_EQ(a.sleeping.angular_threshold, b.sleeping.angular_threshold);
  EXPECT_EQ(a.sleeping.time, b.sleeping.time);
  EXPECT_EQ(a.split_impulse_penetration_threshold, b.split_impulse_penetration_threshold);
  EXPECT_EQ(a.erp, b.erp);
  EXPECT_EQ(a.friction_cone, b.friction_cone);
  EXPECT_EQ(a.full_warm_start, b.full_warm_start);
  EXPECT_EQ(a.collision_margin, b.collision_margin);
  EXPECT_EQ(a.overlap_tolerance, b.overlap_tolerance);
  EXPECT_EQ(a.fall_off_depth, b.fall_off_depth);
  EXPECT_EQ(a.max_linear_speed, b.max_linear_speed);
  EXPECT_EQ(a.max_angular_speed, b.max_angular_speed);
  EXPECT_EQ(a.held.stiffness, b.held.stiffness);
  EXPECT_EQ(a.held.max_force, b.held.max_force);
  EXPECT_EQ(a.table.size, b.table.size);
  EXPECT_EQ(a.table.thickness, b.table.thickness);
  EXPECT_EQ(a.table.height, b.table.height);
  EXPECT_EQ(a.table.friction, b.table.friction);
  EXPECT_EQ(a.table.restitution, b.table.restitution);
  EXPECT_EQ(a.stability.rest_linear_speed, b.stability.rest_linear_speed);
  EXPECT_EQ(a.stability.rest_angular_speed, b.stability.rest_angular_speed);
  EXPECT_EQ(a.stability.rest_time, b.stability.rest_time);
  EXPECT_EQ(a.stability.impact_speed, b.stability.impact_speed);
  EXPECT_EQ(a.stability.support_normal_tolerance, b.stability.support_normal_tolerance);
  EXPECT_EQ(a.stability.flush_angle, b.stability.flush_angle);
  EXPECT_EQ(a.stability.contact_distance, b.stability.contact_distance);
  EXPECT_EQ(a.stability.min_margin, b.stability.min_margin);
  const PublishOptions &p = bare.config.publish, &q = configured.config.publish;
  EXPECT_EQ(p.rate, q.rate);
  EXPECT_EQ(p.clock, q.clock);
  EXPECT_EQ(p.real_time_factor, q.real_time_factor);
  EXPECT_EQ(p.frame_id, q.frame_id);
  EXPECT_EQ(bare.config.data.scene_max_bytes, configured.config.data.scene_max_bytes);
  EXPECT_EQ(bare.config.data.scene_max_bricks, configured.config.data.scene_max_bricks);
  EXPECT_EQ(configured.config.data.scene, "x");
}

/// Writes `text` to a yaml file in the test's temporary directory.
std::string writeYaml(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(RunCommandLine, ConfigFilesThenFlags) {
  const std::string config = writeYaml("run_config.yaml",
                                       "time_step: 0.002\nstability: {mode: none}\n"
                                       "sleeping: {enabled: false}\nscene: tower10\n");
  RunCommandLine cli;
  Status s = parseRunCommandLine({"--config", config}, "/pkg", &cli);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_EQ(cli.config.world.time_step, 0.002);
  EXPECT_EQ(cli.config.world.stability.mode, "none");
  EXPECT_FALSE(cli.config.world.sleeping.enabled);
  EXPECT_EQ(cli.config.data.scene, "tower10");  // no --scene needed
  // Flags win over the file, wherever they stand.
  s = parseRunCommandLine({"--mode", "com", "--config", config, "--time-step", "0.003"}, "/pkg",
                          &cli);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_EQ(cli.config.world.stability.mode, "com");
  EXPECT_EQ(cli.config.world.time_step, 0.003);
}

TEST(RunCommandLine, ConfigTyposAndBadValuesAreNamedWithTheFile) {
  const std::string typo = writeYaml("typo.yaml", "time_stepp: 0.002\n");
  const std::string nested = writeYaml("nested.yaml", "stability: {rest_tme: 0.1}\n");
  const std::string bad = writeYaml("bad.yaml", "table: {size: [1.0, -2.0]}\n");
  const std::string wrong_type = writeYaml("wrong_type.yaml", "solver_iterations: many\n");
  struct Case {
    std::string file;
    std::vector<std::string> expected;
  };
  const Case cases[] = {
      {typo, {typo, "time_stepp", "not a known parameter"}},
      {nested, {"stability/rest_tme", "not a known parameter"}},
      {bad, {"table/size = -2"}},
      {wrong_type, {"solver_iterations", "many"}},
      {"/nonexistent/config.yaml", {"/nonexistent/config.yaml"}},
      {writeYaml("no_bricks.yaml", "scene_max_bricks: 0\n"),
       {"scene_max_bricks = 0", "must be in [1, 1000000] bricks"}},
      {writeYaml("many_bricks.yaml", "scene_max_bricks: 1000001\n"), {"scene_max_bricks"}},
  };
  for (const Case& c : cases) {
    RunCommandLine cli;
    cli.config.world.time_step = 0.005;  // a marker: a refusal changes nothing
    const Status s = parseRunCommandLine({"--config", c.file, "--scene", "x"}, "/pkg", &cli);
    EXPECT_FALSE(s.ok) << c.file;
    for (const std::string& word : c.expected)
      EXPECT_NE(s.message.find(word), std::string::npos) << s.message;
    EXPECT_EQ(cli.config.world.time_step, 0.005);
  }
}

TEST(RunCommandLine, HelpListsEveryModeOfTheRegistry) {
  const std::string usage = runUsage();
  for (const std::string& mode : availableStabilityModes()) {
    EXPECT_FALSE(describeStabilityMode(mode).empty()) << mode;
    EXPECT_NE(usage.find(mode + ": " + describeStabilityMode(mode)), std::string::npos) << usage;
  }
  EXPECT_TRUE(describeStabilityMode("magic").empty());
}

TEST(RunCommandLine, HelpNamesWhereThePackageDataIs) {
  // From an install space that is share/brick_stack_sim, not the source tree.
  EXPECT_NE(runUsage("/opt/ws/install/share/brick_stack_sim")
                .find("urdf/, config/ and scenes/: /opt/ws/install/share/brick_stack_sim\n"),
            std::string::npos);
  EXPECT_EQ(runUsage().find("urdf/, config/ and scenes/:"), std::string::npos);
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
      {{"--scene", "x", "--mode", "Com"}, "not available"},
      {{"--scene", "x", "--config"}, "--config needs a value"},
      {{"--scene", "x", "--duration", "-3"}, "--duration"},
      {{"--mode", "none"}, "--scene is required"},
      {{"tower10"}, "unexpected argument"},
      {{"--scene", "tower10", "--duration", "1e300"}, "--duration must be in [0, 1000000] s"},
  };
  for (const Case& c : cases) {
    RunCommandLine cli;
    const Status s = parseRunCommandLine(c.args, "/pkg", &cli);
    EXPECT_FALSE(s.ok) << c.expected;
    EXPECT_NE(s.message.find(c.expected), std::string::npos) << s.message;
  }
}

/// Runs the real executable, killed after `timeout_seconds` (exit 124),
/// after the shell commands `before` (a ulimit); returns its exit code (-1
/// when it did not exit, as on an abort) and fills `output` with stderr.
int runExecutable(const std::string& args, std::string* output, int timeout_seconds = 300,
                  const std::string& before = "") {
  const std::string command = before + "timeout " + std::to_string(timeout_seconds) + " " +
                              std::string(STACK_SIM_RUN_PATH) + " " + args + " 2>&1 >/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buffer[512];
  output->clear();
  while (std::fgets(buffer, sizeof buffer, pipe)) *output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(StackSimRun, RefusesAFileThatIsNotASceneAtOnce) {
  // /dev/zero once made the runner read until it was killed for memory.
  std::string output;
  EXPECT_EQ(runExecutable("--scene /dev/zero --duration 1", &output), 1) << output;
  EXPECT_NE(output.find("not a regular file"), std::string::npos) << output;
  EXPECT_EQ(runExecutable("--scene /tmp --duration 1", &output), 1) << output;
  EXPECT_NE(output.find("is a directory"), std::string::npos) << output;
}

TEST(StackSimRun, ASceneOverTheBrickCapIsRefusedBeforeItIsBuilt) {
  // 3.4 kB asking for 5 million bricks once took the runner down with an
  // uncaught std::bad_alloc.
  std::string yaml = "generator:\n";
  for (int i = 0; i < 50; ++i)
    yaml += "  - {name: tower, layers: 10000, bricks_per_layer: 2, grid: [5, 1]}\n";
  const std::string scene = writeYaml("run_over_cap.yaml", yaml);
  std::string output;
  EXPECT_EQ(runExecutable("--scene " + scene + " --duration 1", &output, 20), 1) << output;
  EXPECT_NE(output.find("scene 'run_over_cap': generator 2 (tower) would bring the scene to 200000 "
                        "bricks: at most 100000 (scene_max_bricks)"),
            std::string::npos)
      << output;
  // The cap is the config's, as the node's is its parameter.
  const std::string config = writeYaml("run_cap.yaml", "scene_max_bricks: 20\n");
  const std::string towers =
      writeYaml("run_towers.yaml",
                "generator:\n  - {name: tower, layers: 5}\n  - {name: tower, "
                "layers: 6, origin: [0.3, 0]}\n");
  EXPECT_EQ(runExecutable("--config " + config + " --scene " + towers + " --duration 0.1", &output),
            1)
      << output;
  EXPECT_NE(output.find("generator 2 (tower) would bring the scene to 22 bricks: at most 20"),
            std::string::npos)
      << output;
  EXPECT_EQ(runExecutable("--scene " + towers + " --duration 0.1", &output), 0) << output;
}

TEST(StackSimRun, RunningOutOfMemoryIsAFailedRunNotAnAbort) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizers reserve more address space than the limit allows";
#endif
  // 100 000 listed bricks: within the cap, but its YAML tree alone takes
  // some 500 MB, more than the 200 MB of address space the runner gets here.
  std::ostringstream yaml;
  yaml << "bricks:\n";
  for (int i = 0; i < 100000; ++i)
    yaml << "  - {id: b" << i << ", at: " << i << ", position: [" << (i % 50) * 0.15 - 3.5 << ", "
         << (i / 50 % 50) * 0.15 - 3.5 << ", 0.0039]}\n";
  const std::string scene = writeYaml("run_out_of_memory.yaml", yaml.str());
  std::string output;
  // The same limit leaves room for a small run.
  EXPECT_EQ(runExecutable("--scene single_drop --duration 0.1", &output, 60, "ulimit -v 200000;"),
            0)
      << output;
  EXPECT_EQ(runExecutable("--scene " + scene + " --duration 0", &output, 60, "ulimit -v 200000;"),
            1)
      << output;
  EXPECT_NE(output.find("stack_sim_run: out of memory while running the scene (std::bad_alloc)"),
            std::string::npos)
      << output;
  std::remove(scene.c_str());
}

TEST(StackSimRun, ASceneWithABadBrickIsRefusedUnlessAskedToSkipIt) {
  // Such a scene once loaded, ran and exited 0 with "refused 1".
  const std::string outside = writeYaml("run_outside.yaml",
                                        "bricks:\n"
                                        "  - {id: a, position: [0, 0, 0.0039]}\n"
                                        "  - {id: far, position: [1e300, 0, 0.0039]}\n");
  std::string output;
  EXPECT_EQ(runExecutable("--scene " + outside + " --duration 0.1", &output), 1) << output;
  EXPECT_NE(output.find("the first (2 of 2, id 'far')"), std::string::npos) << output;
  EXPECT_NE(output.find("outside the world box"), std::string::npos) << output;
  EXPECT_NE(output.find("--skip-bad-bricks"), std::string::npos) << output;
  EXPECT_EQ(runExecutable("--scene " + outside + " --duration 0.1 --skip-bad-bricks", &output), 0)
      << output;
  EXPECT_NE(output.find("refused 1"), std::string::npos) << output;

  // An overlap shows only when the brick is due: the run says so and fails.
  const std::string overlap = writeYaml("run_overlap.yaml",
                                        "bricks:\n"
                                        "  - {id: a, at: 0.0, position: [0, 0, 0.0039]}\n"
                                        "  - {id: b, at: 0.05, position: [0.01, 0, 0.0039]}\n");
  EXPECT_EQ(runExecutable("--scene " + overlap + " --duration 0.1", &output), 1) << output;
  EXPECT_NE(output.find("the first b at t=0.05 s: pose overlaps brick 'a'"), std::string::npos)
      << output;
  EXPECT_EQ(runExecutable("--scene " + overlap + " --duration 0.1 --skip-bad-bricks", &output), 0)
      << output;

  const std::string twice = writeYaml("run_twice.yaml",
                                      "bricks:\n"
                                      "  - {id: a, at: 0.0, position: [0, 0, 0.0039]}\n"
                                      "  - {id: a, at: 1.0, position: [0.2, 0, 0.0039]}\n");
  EXPECT_EQ(runExecutable("--scene " + twice + " --duration 0.1", &output), 1) << output;
  EXPECT_NE(output.find("id 'a' appears twice"), std::string::npos) << output;
}

TEST(StackSimRun, AnUnwritableReportPathFailsBeforeTheRun) {
  // 1e5 s of a 10-layer tower would take minutes: `timeout` would kill a
  // runner that checked the path only after the run (exit 124).
  std::string output;
  EXPECT_EQ(runExecutable("--scene tower10 --duration 100000 --report /no_such_dir/report.json",
                          &output, 20),
            1)
      << output;
  EXPECT_NE(output.find("cannot write report '/no_such_dir/report.json'"), std::string::npos)
      << output;
  const std::string fresh = ::testing::TempDir() + "/not_left_behind.json";
  std::remove(fresh.c_str());
  EXPECT_EQ(runExecutable("--scene no_such_scene --report " + fresh, &output), 1) << output;
  EXPECT_FALSE(std::ifstream(fresh)) << "a failed run left an empty report behind";
}

TEST(StackSimRun, SavesTheStateItEndsInAsASceneThatRunsOnFromThere) {
  // A plank dropped onto the table and one dropped past its edge, which
  // ends on the floor, where no scene can place it.
  const std::string scene = writeYaml("run_save_from.yaml",
                                      "name: two_drops\n"
                                      "bricks:\n"
                                      "  - {id: on, position: [0, 0, 0.05]}\n"
                                      "  - {id: past, position: [0.65, 0, 0.05]}\n");
  const std::string saved = ::testing::TempDir() + "/stack_sim_run_end_state.yaml";
  std::remove(saved.c_str());
  std::string output;
  ASSERT_EQ(runExecutable("--scene " + scene + " --duration 1 --save-scene " + saved, &output), 0)
      << output;
  EXPECT_NE(output.find("1 brick(s), 1 left out that no scene can place, the first past"),
            std::string::npos)
      << output;
  std::ifstream file(saved);
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_NE(text.str().find("name: two_drops"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("id: on"), std::string::npos) << text.str();
  EXPECT_EQ(text.str().find("id: past"), std::string::npos) << text.str();
  // Run again from there: the plank lies where it landed, and stays.
  ASSERT_EQ(runExecutable("--scene " + saved + " --duration 0.5", &output), 0) << output;
  EXPECT_NE(output.find("1 brick,"), std::string::npos) << output;
  EXPECT_NE(output.find("largest displacement 0.000 mm"), std::string::npos) << output;

  EXPECT_EQ(runExecutable("--scene tower10 --duration 100000 --save-scene /no_such_dir/end.yaml",
                          &output, 20),
            1)
      << output;
  EXPECT_NE(output.find("cannot write scene '/no_such_dir/end.yaml'"), std::string::npos) << output;
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

  // The node's own yaml, as docs/design.md, "Options" promises.
  ASSERT_EQ(runExecutable("--config " + test::dataPath("config/stability.yaml") +
                              " --scene single_drop --duration 0.2 --report " + report_path,
                          &output),
            0)
      << output;
  EXPECT_NE(output.find("mode com"), std::string::npos) << output;
  const std::string typo = writeYaml("run_typo.yaml", "stability: {mdoe: none}\n");
  EXPECT_NE(runExecutable("--config " + typo + " --scene single_drop", &output), 0);
  EXPECT_NE(output.find("stability/mdoe"), std::string::npos) << output;

  EXPECT_NE(runExecutable("--scene no_such_scene", &output), 0);
  EXPECT_NE(output.find("unknown scene 'no_such_scene'"), std::string::npos) << output;
  EXPECT_NE(runExecutable("--scene single_drop --frobnicate", &output), 0);
  EXPECT_NE(output.find("--frobnicate"), std::string::npos) << output;
}

}  // namespace
}  // namespace brick_stack_sim
