// blueprint_builder: builds a scene on a running brick_sim through its
// services and prints "demo summary: ..."; exits 1 when the structure did not
// do what the scene expects, naming the brick that fell (docs/ros_interface.md,
// "blueprint_builder").
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>

#include <ros/package.h>
#include <ros/ros.h>
#include <unistd.h>

#include "brick_stack_sim/planner/blueprint_builder.h"

namespace {

/// Whether this process was started by roslaunch (its parent runs it).
bool startedByRoslaunch() {
  std::ifstream cmdline("/proc/" + std::to_string(getppid()) + "/cmdline");
  const std::string command((std::istreambuf_iterator<char>(cmdline)),
                            std::istreambuf_iterator<char>());
  return command.find("roslaunch") != std::string::npos;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "blueprint_builder");
  ros::NodeHandle private_nh("~");
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
    ROS_FATAL("blueprint_builder: %s", status.message.c_str());
    return 2;
  }
  std::printf("%s\n%s: %s\n", outcome.summary_line.c_str(), outcome.met ? "result" : "FAILED",
              outcome.verdict.c_str());
  std::fflush(stdout);

  // A headless demo ends when its build does. A `required` node would end
  // roslaunch too, but with a red "REQUIRED process has died" that reads
  // as a failure; a Ctrl-C from the node ends it as a user would.
  bool end_launch = false;
  private_nh.param("end_launch", end_launch, false);
  if (end_launch && startedByRoslaunch()) {
    kill(getppid(), SIGINT);
    // roslaunch now stops its nodes, this one too: wait for it (a while, in
    // case it never comes) so that its log shows a node killed on exit, not
    // one that died on its own.
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::ok() && ros::WallTime::now() < give_up) ros::WallDuration(0.05).sleep();
  }
  return outcome.met ? 0 : 1;
}
