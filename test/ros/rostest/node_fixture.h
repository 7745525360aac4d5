#pragma once
// The base fixture of the rostests that drive a running node: a thin gtest
// layer over client::SimClient. It waits for the node, holds the client and
// wraps the calls the tests share, each expecting that the call reached the
// node. Each test file derives its own fixture, which brings the node to its
// starting state in SetUp.

#include <dirent.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <ros/service_traits.h>

#include "brick_stack_sim/client/pose_msg.h"
#include "brick_stack_sim/client/sim_client.h"
#include "brick_stack_sim/ros/interface_names.h"

namespace brick_stack_sim {
namespace test {

using client::poseAt;

/// The node's response in `reply`, expecting that the call reached the node.
template <typename Response>
Response expectReached(const client::Reply<Response>& reply) {
  EXPECT_TRUE(reply.reached) << reply.message;
  return reply.response;
}

// `request` through the client's method for its service: a test that builds
// a request field by field sends it whole.
inline client::Reply<PlaceBrick::Response> send(client::SimClient& sim,
                                                const PlaceBrick::Request& request) {
  return sim.placeBrick(request);
}
inline client::Reply<RemoveBrick::Response> send(client::SimClient& sim,
                                                 const RemoveBrick::Request& request) {
  return sim.removeBrick(request.id);
}
inline client::Reply<ResetScene::Response> send(client::SimClient& sim,
                                                const ResetScene::Request& request) {
  return sim.reset(request.scene);
}
inline client::Reply<GetBricks::Response> send(client::SimClient& sim,
                                               const GetBricks::Request& request) {
  return sim.getBricks(request.ids);
}
inline client::Reply<PushBrick::Response> send(client::SimClient& sim,
                                               const PushBrick::Request& request) {
  return sim.pushBrick(request);
}
inline client::Reply<QueryPlacement::Response> send(client::SimClient& sim,
                                                    const QueryPlacement::Request& request) {
  return sim.queryPlacement(request);
}
inline client::Reply<QueryPlacements::Response> send(client::SimClient& sim,
                                                     const QueryPlacements::Request& request) {
  return sim.queryPlacements(request);
}
inline client::Reply<std_srvs::SetBool::Response> send(client::SimClient& sim,
                                                       const std_srvs::SetBool::Request& request) {
  return sim.pause(request.data);
}
inline client::Reply<StepSimulation::Response> send(client::SimClient& sim,
                                                    const StepSimulation::Request& request) {
  return sim.step(request.steps);
}
inline client::Reply<GraspBrick::Response> send(client::SimClient& sim,
                                                const GraspBrick::Request& request) {
  return sim.graspBrick(request.id);
}
inline client::Reply<ReleaseBrick::Response> send(client::SimClient& sim,
                                                  const ReleaseBrick::Request& request) {
  return sim.releaseBrick(request.id, request.twist);
}

/// Sends `srv.request` through `sim` from a thread of its own and waits at
/// most `seconds` [s] for the answer (into `srv.response`): a roscpp call has
/// no timeout, and a node that never answers must fail the test instead of
/// hanging it. The caller does not use `sim` meanwhile. False when the call
/// did not reach the node or did not come back in time (the thread is then
/// left behind, holding `sim`; the test ends anyway).
template <typename Service>
bool callWithin(const std::shared_ptr<client::SimClient>& sim, Service& srv, double seconds) {
  using Reply = decltype(send(*sim, srv.request));
  auto answer = std::make_shared<std::promise<Reply>>();
  std::future<Reply> done = answer->get_future();
  std::thread([sim, request = srv.request, answer] {
    answer->set_value(send(*sim, request));
  }).detach();
  if (done.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
    ADD_FAILURE() << ros::service_traits::datatype<Service>() << " did not answer within "
                  << seconds << " s";
    return false;
  }
  const Reply reply = done.get();
  EXPECT_TRUE(reply.reached) << reply.message;
  srv.response = reply.response;
  return reply.reached;
}

/// The node's resident memory [kB], found by its name on the command line
/// roslaunch gave it (__name:=brick_sim); 0 when not found.
inline long nodeResidentKilobytes() {
  DIR* proc = opendir("/proc");
  if (!proc) return 0;
  long rss = 0;
  while (dirent* entry = readdir(proc)) {
    const std::string pid = entry->d_name;
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream cmdline("/proc/" + pid + "/cmdline");
    std::string args((std::istreambuf_iterator<char>(cmdline)), std::istreambuf_iterator<char>());
    if (args.find("brick_stack_sim_node") == std::string::npos ||
        args.find(std::string("__name:=") + ros_adapter::kNodeName + '\0') == std::string::npos)
      continue;
    std::ifstream status("/proc/" + pid + "/status");
    std::string line;
    while (std::getline(status, line))
      if (line.rfind("VmRSS:", 0) == 0) rss = std::stol(line.substr(6));
  }
  closedir(proc);
  return rss;
}

class NodeFixture : public ::testing::Test {
 protected:
  /// Waits for the node. A derived SetUp calls this first and returns if
  /// HasFatalFailure().
  void SetUp() override {
    const client::CallResult up = sim_->waitForNode(60.0);
    ASSERT_TRUE(up.ok) << "the node did not come up: " << up.message;
  }

  /// Polls `done` for up to `seconds` of wall time (callbacks run in the spinner).
  static bool waitFor(const std::function<bool()>& done, double seconds) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::WallTime::now() < end) {
      if (done()) return true;
      ros::WallDuration(0.01).sleep();
    }
    return done();
  }

  PlaceBrick::Response place(const std::string& id, double x, double y, double z, double yaw = 0.0,
                             const std::string& type = "kapla") {
    PlaceBrick srv;
    srv.request.id = id;
    srv.request.type = type;
    srv.request.pose = poseAt(x, y, z, yaw);
    return call(srv);
  }

  /// Sends `srv.request` and returns the answer, also left in `srv.response`.
  template <typename Service>
  typename Service::Response call(Service& srv) {
    srv.response = expectReached(send(*sim_, srv.request));
    return srv.response;
  }

  std::vector<Brick> bricks() {
    const client::Reply<GetBricks::Response> reply = sim_->getBricks();
    EXPECT_TRUE(reply.reached) << reply.message;
    EXPECT_TRUE(reply.response.success) << reply.response.message;
    return reply.response.bricks;
  }

  bool setPaused(bool paused) { return sim_->pause(paused).ok; }

  StepSimulation::Response step(unsigned steps) { return expectReached(sim_->step(steps)); }

  ros::NodeHandle nh_;
  /// The node's services and topics, with persistent connections: a test of
  /// thousands of calls needs them, since roscpp's one-connection-per-call
  /// clients fail now and then under load, which is not the node's doing.
  /// Shared with the threads of callWithin.
  std::shared_ptr<client::SimClient> sim_ = std::make_shared<client::SimClient>();
};

/// The main() of a rostest gtest node named `node_name`: service calls are
/// answered while a spinner thread takes the topics the tests subscribe to.
inline int runNodeTests(int argc, char** argv, const char* node_name) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, node_name);
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  spinner.stop();
  ros::shutdown();
  return result;
}

}  // namespace test
}  // namespace brick_stack_sim
