// blueprint_builder: builds a scene on a running brick_sim through its
// services and prints "demo summary: ..."; exits 0 when the structure did
// what the scene expects, 1 when not, naming the brick that fell, 2 when it
// could not run; writes that status to ~status_file and ends a headless
// launch on every exit (docs/ros_interface.md, "blueprint_builder").
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <ros/master.h>
#include <ros/package.h>
#include <ros/ros.h>

#include "brick_stack_sim/planner/blueprint_builder.h"

namespace {

/// The exit statuses of docs/ros_interface.md, "blueprint_builder".
constexpr int kMet = 0;
constexpr int kNotMet = 1;
constexpr int kCouldNotRun = 2;

/// Whether this process was started by roslaunch (its parent runs it).
bool startedByRoslaunch() {
  std::ifstream cmdline("/proc/" + std::to_string(getppid()) + "/cmdline");
  const std::string command((std::istreambuf_iterator<char>(cmdline)),
                            std::istreambuf_iterator<char>());
  return command.find("roslaunch") != std::string::npos;
}

/// Whether the master lists a node called `name` (a full name, /left/...).
bool nodeRunning(const std::string& name) {
  std::vector<std::string> nodes;
  if (!ros::master::getNodes(nodes)) return false;
  return std::find(nodes.begin(), nodes.end(), name) != nodes.end();
}

/// Writes `status` as one line to `path` (if not empty), whole or not at all:
/// a waiting builder or script sees either no file or the status.
void writeStatusFile(const std::string& path, int status) {
  if (path.empty()) return;
  const std::string partial = path + ".partial";
  {
    std::ofstream file(partial);
    file << status << '\n';
    if (!file) {
      ROS_ERROR("blueprint_builder: cannot write ~status_file '%s'", partial.c_str());
      return;
    }
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0)
    ROS_ERROR("blueprint_builder: cannot write ~status_file '%s'", path.c_str());
}

/// How the builder ends: read at the start, since a master that went away
/// during the build could not be asked at the end.
struct Ending {
  std::string status_file;  ///< Where the exit status goes; empty: nowhere.
  bool end_launch = false;
  std::string end_launch_after;  ///< Another builder of the launch, to wait for (its full name).
  double wait = 60.0;            ///< At most this long [s] (wall time), ~service_wait.
};

Ending readEnding(const ros::NodeHandle& private_nh) {
  Ending ending;
  private_nh.param("status_file", ending.status_file, ending.status_file);
  private_nh.param("end_launch", ending.end_launch, ending.end_launch);
  private_nh.param("end_launch_after", ending.end_launch_after, ending.end_launch_after);
  private_nh.param("service_wait", ending.wait, ending.wait);
  return ending;
}

/// A headless demo ends when its build does, whatever the outcome. A
/// `required` node would end roslaunch too, but with a red "REQUIRED process
/// has died" that reads as a failure; a Ctrl-C from the node ends it as a
/// user would. With ~end_launch_after (the full name of another builder of
/// the same launch) it first waits, at most ~service_wait, for that builder to
/// end too.
void endLaunch(const Ending& ending) {
  if (!ending.end_launch || !startedByRoslaunch()) return;
  const ros::WallTime give_up_waiting = ros::WallTime::now() + ros::WallDuration(ending.wait);
  while (!ending.end_launch_after.empty() && nodeRunning(ending.end_launch_after) && ros::ok() &&
         ros::WallTime::now() < give_up_waiting)
    ros::WallDuration(0.2).sleep();
  kill(getppid(), SIGINT);
  // roslaunch now stops its nodes, this one too: wait for it (a while, in
  // case it never comes) so that its log shows a node killed on exit, not
  // one that died on its own.
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::ok() && ros::WallTime::now() < give_up) ros::WallDuration(0.05).sleep();
}

/// Reads the options, builds the scene and prints the summary and verdict;
/// returns the exit status.
int run(const ros::NodeHandle& private_nh) {
  namespace planner = brick_stack_sim::planner;
  planner::BuilderOptions options;
  brick_stack_sim::Status status =
      planner::readBuilderOptions(private_nh, ros::package::getPath("brick_stack_sim"), &options);
  brick_stack_sim::Scene scene;
  planner::BlueprintBuilder builder(ros::NodeHandle(), options);
  if (status) status = builder.loadScene(&scene);
  planner::BuildOutcome outcome;
  if (status) status = builder.build(scene, &outcome);
  if (!status) {
    ROS_FATAL("%sblueprint_builder: %s", planner::linePrefix(options).c_str(),
              status.message.c_str());
    return kCouldNotRun;
  }
  const std::string prefix = planner::linePrefix(options);
  std::printf("%s%s\n%s%s: %s\n", prefix.c_str(), outcome.summary_line.c_str(), prefix.c_str(),
              outcome.met ? "result" : "FAILED", outcome.verdict.c_str());
  std::fflush(stdout);
  return outcome.met ? kMet : kNotMet;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "blueprint_builder");
  ros::NodeHandle private_nh("~");
  const Ending ending = readEnding(private_nh);
  const int status = run(private_nh);
  writeStatusFile(ending.status_file, status);
  endLaunch(ending);
  return status;
}
