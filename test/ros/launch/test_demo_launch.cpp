// A headless demo ends when its builder ends, whatever for, and tells how
// (docs/ros_interface.md, "Launch files"): demo.launch and compare.launch on a
// scene that does not exist, run by scripts/demo_with_status.sh as a script
// would, each on a master of its own on a free port. The builder cannot run,
// so the status must be 2, and the launch must end well before its time
// limit, not stay up until someone presses Ctrl-C.
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

namespace {

/// A TCP port nobody listens on now (the kernel's pick).
int freePort() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof address;
  int port = -1;
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0)
    port = ntohs(address.sin_port);
  close(fd);
  return port;
}

struct DemoRun {
  int status = -1;  ///< Exit status, or -1 when it did not exit normally.
  double seconds = 0.0;
  std::string output;
};

/// Runs scripts/demo_with_status.sh with `arguments` on a master of its own,
/// killed with its whole process group after `limit` seconds.
DemoRun runDemo(const std::string& arguments, int limit) {
  const int port = freePort();
  EXPECT_GT(port, 0);
  char log_dir[] = "/tmp/demo_launch_test_XXXXXX";
  EXPECT_NE(mkdtemp(log_dir), nullptr);
  const std::string command = "ROS_MASTER_URI=http://localhost:" + std::to_string(port) +
                              " ROS_LOG_DIR=" + log_dir + " timeout -k 5 " + std::to_string(limit) +
                              " bash " + DEMO_WITH_STATUS_PATH + " " + arguments + " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  DemoRun run;
  FILE* pipe = popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  if (!pipe) return run;
  std::array<char, 512> chunk;
  while (fgets(chunk.data(), chunk.size(), pipe)) run.output += chunk.data();
  const int status = pclose(pipe);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) run.status = WEXITSTATUS(status);
  std::system(("rm -rf " + std::string(log_dir)).c_str());
  return run;
}

/// timeout(1) exits 124 (or 137 after -k) when it had to stop the command.
constexpr int kLimit = 90;

TEST(DemoLaunch, AHeadlessDemoOnAnUnknownSceneEndsAndTellsTwo) {
  const DemoRun run = runDemo("demo.launch scene:=nonexistent", kLimit);
  ASSERT_NE(run.status, 124) << "the launch did not end by itself within " << kLimit << " s\n"
                             << run.output;
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_LT(run.seconds, 45.0) << run.output;
  EXPECT_NE(run.output.find("unknown scene 'nonexistent'"), std::string::npos) << run.output;
}

TEST(DemoLaunch, AHeadlessCompareEndsWhenBothBuildersHaveAndTellsTheWorse) {
  const DemoRun run = runDemo("compare.launch gui:=false scene:=nonexistent", kLimit);
  ASSERT_NE(run.status, 124) << "the launch did not end by itself within " << kLimit << " s\n"
                             << run.output;
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_LT(run.seconds, 45.0) << run.output;
  // Both builders ran and failed before the launch ended.
  std::size_t failures = 0;
  for (std::size_t at = run.output.find("unknown scene 'nonexistent'"); at != std::string::npos;
       at = run.output.find("unknown scene 'nonexistent'", at + 1))
    ++failures;
  EXPECT_EQ(failures, 2u) << run.output;
}

}  // namespace
