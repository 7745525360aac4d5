#pragma once
// The base fixture of the rostests that drive a running node through its
// services: it waits for the node, holds one client per service and wraps the
// calls the tests share. Each test file derives its own fixture, which brings
// the node to its starting state in SetUp.

#include <chrono>
#include <cmath>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

#include "brick_stack_sim/GetBricks.h"
#include "brick_stack_sim/PlaceBrick.h"
#include "brick_stack_sim/PushBrick.h"
#include "brick_stack_sim/QueryPlacement.h"
#include "brick_stack_sim/RemoveBrick.h"
#include "brick_stack_sim/ResetScene.h"
#include "brick_stack_sim/StepSimulation.h"

namespace brick_stack_sim {
namespace test {

/// Calls `client` from a thread of its own and waits at most `seconds` [s]:
/// a rospy or roscpp call has no timeout, and a node that never answers must
/// fail the test instead of hanging it. False when the call failed or did not
/// come back in time (the thread is then left behind; the test ends anyway).
template <typename Service>
bool callWithin(ros::ServiceClient& client, Service& srv, double seconds) {
  auto answer = std::make_shared<std::promise<bool>>();
  std::future<bool> done = answer->get_future();
  auto shared = std::make_shared<Service>(srv);
  std::thread([client, shared, answer]() mutable {
    answer->set_value(client.call(*shared));
  }).detach();
  if (done.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
    ADD_FAILURE() << client.getService() << " did not answer within " << seconds << " s";
    return false;
  }
  const bool called = done.get();
  EXPECT_TRUE(called) << "call to " << client.getService() << " failed";
  srv = *shared;
  return called;
}

class NodeFixture : public ::testing::Test {
 protected:
  /// Waits for the node and connects the clients. A derived SetUp calls this
  /// first and returns if HasFatalFailure().
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService("/brick_sim/step", ros::Duration(60.0)))
        << "the node did not come up";
    connectClients(false);
  }

  /// Persistent clients keep one connection each: a test of thousands of
  /// calls needs them, since roscpp's one-connection-per-call clients fail
  /// now and then under load (ros/ros_comm#1976), which is not the node's doing.
  void connectClients(bool persistent) {
    place_ = nh_.serviceClient<PlaceBrick>("/brick_sim/place_brick", persistent);
    remove_ = nh_.serviceClient<RemoveBrick>("/brick_sim/remove_brick", persistent);
    reset_ = nh_.serviceClient<ResetScene>("/brick_sim/reset", persistent);
    get_ = nh_.serviceClient<GetBricks>("/brick_sim/get_bricks", persistent);
    push_ = nh_.serviceClient<PushBrick>("/brick_sim/push_brick", persistent);
    pause_ = nh_.serviceClient<std_srvs::SetBool>("/brick_sim/pause", persistent);
    step_ = nh_.serviceClient<StepSimulation>("/brick_sim/step", persistent);
    query_ = nh_.serviceClient<QueryPlacement>("/brick_sim/query_placement", persistent);
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
    srv.request.pose.position.x = x;
    srv.request.pose.position.y = y;
    srv.request.pose.position.z = z;
    srv.request.pose.orientation.z = std::sin(yaw / 2);
    srv.request.pose.orientation.w = std::cos(yaw / 2);
    return call(place_, srv);
  }

  template <typename Service>
  typename Service::Response call(ros::ServiceClient& client, Service& srv) {
    EXPECT_TRUE(client.call(srv)) << "call to " << client.getService() << " failed";
    return srv.response;
  }

  std::vector<Brick> bricks() {
    GetBricks srv;
    EXPECT_TRUE(get_.call(srv));
    EXPECT_TRUE(srv.response.success) << srv.response.message;
    return srv.response.bricks;
  }

  bool setPaused(bool paused) {
    std_srvs::SetBool srv;
    srv.request.data = paused;
    return pause_.call(srv) && srv.response.success;
  }

  StepSimulation::Response step(unsigned steps) {
    StepSimulation srv;
    srv.request.steps = steps;
    return call(step_, srv);
  }

  ros::NodeHandle nh_;
  ros::ServiceClient place_, remove_, reset_, get_, push_, pause_, step_, query_;
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
