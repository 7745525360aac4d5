// Long work does not stop the node from answering: while one client runs a
// ~step of a million steps on a busy scene, ~get_bricks is answered within
// 100 ms (99th percentile), ~bricks follows wall time, not sim time, and the
// step still makes progress.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "brick_stack_sim/ros/interface_names.h"
#include "brick_stack_sim/ros/node.h"
#include "node_fixture.h"

namespace {

using namespace brick_stack_sim;

/// Calls made during the step; at 20 ms apart, a few seconds of it.
constexpr int kLatencySamples = 200;
constexpr double kCallSpacing = 0.02;   ///< [s]
constexpr double kMaxP99Latency = 0.1;  ///< [s]

class Responsiveness : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    ASSERT_TRUE(setPaused(true));
    std::string scene;
    ASSERT_TRUE(ros::param::get("~busy_scene", scene));
    const client::Reply<ResetScene::Response> reset = sim_->reset(scene);
    ASSERT_TRUE(reset.reached) << reset.message;
    ASSERT_TRUE(reset.response.success) << reset.response.message;
    // The pile is placed over its first steps: every brick in before timing.
    ASSERT_TRUE(step(2000).success);
    ASSERT_EQ(bricks().size(), 50u);
  }

  /// ~get_bricks from its own connection, timed [s].
  double timedGetBricks(client::SimClient& sim, double* sim_time) {
    const auto start = std::chrono::steady_clock::now();
    const client::Reply<GetBricks::Response> reply = sim.getBricks();
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    EXPECT_TRUE(reply.reached) << reply.message;
    const GetBricks::Response& response = reply.response;
    EXPECT_TRUE(response.success) << response.message;
    EXPECT_EQ(response.bricks.size(), 50u);
    // Stamps are wall time here (no /clock); the message says the sim time:
    // "50 bricks at t=12.345 s".
    const std::size_t at = response.message.find("t=");
    if (at != std::string::npos) *sim_time = std::stod(response.message.substr(at + 2));
    return took.count();
  }
};

TEST_F(Responsiveness, GetBricksAnsweredDuringMillionStepRequest) {
  std::mutex count_mutex;
  int bricks_messages = 0;
  ros::Subscriber counter = sim_->subscribeBricks(
      [&](const BrickArray::ConstPtr&) {
        std::lock_guard<std::mutex> lock(count_mutex);
        ++bricks_messages;
      },
      1000);
  ASSERT_TRUE(waitFor([&] { return counter.getNumPublishers() > 0; }, 10.0));

  double start_time = 0.0;
  client::SimClient get_client;  // persistent
  timedGetBricks(get_client, &start_time);

  // The step runs in its own thread: its call returns only when it is done
  // or interrupted.
  std::promise<StepSimulation::Response> step_done;
  std::thread stepper([&] {
    client::SimClient step_client;
    const client::Reply<StepSimulation::Response> reply =
        step_client.step(ros_adapter::kMaxStepsPerRequest);
    EXPECT_TRUE(reply.reached) << reply.message;
    step_done.set_value(reply.response);
  });
  std::future<StepSimulation::Response> step_answer = step_done.get_future();
  ros::WallDuration(0.2).sleep();  // the step is under way
  {
    std::lock_guard<std::mutex> lock(count_mutex);
    bricks_messages = 0;
  }
  const ros::WallTime window_start = ros::WallTime::now();
  std::vector<double> latencies;
  double last_time = 0.0;
  for (int i = 0; i < kLatencySamples; ++i) {
    latencies.push_back(timedGetBricks(get_client, &last_time));
    ros::WallDuration(kCallSpacing).sleep();
  }
  const double window = (ros::WallTime::now() - window_start).toSec();
  int messages = 0;
  {
    std::lock_guard<std::mutex> lock(count_mutex);
    messages = bricks_messages;
  }
  ASSERT_EQ(step_answer.wait_for(std::chrono::seconds(0)), std::future_status::timeout)
      << "the million steps ended before the sampling did: the scene is not busy enough "
         "to test anything";

  // Resuming interrupts the step: the test need not wait for all of it.
  ASSERT_TRUE(setPaused(false));
  ASSERT_EQ(step_answer.wait_for(std::chrono::seconds(10)), std::future_status::ready)
      << "the step did not stop when the simulation was resumed";
  stepper.join();
  const StepSimulation::Response answer = step_answer.get();
  EXPECT_FALSE(answer.success);
  EXPECT_NE(answer.message.find("resumed"), std::string::npos) << answer.message;

  std::sort(latencies.begin(), latencies.end());
  const double median = latencies[latencies.size() / 2];
  const double p99 = latencies[latencies.size() * 99 / 100];
  const double worst = latencies.back();
  const double simulated = last_time - start_time;
  const double rate = messages / window;
  std::printf(
      "get_bricks during a ~step of %u steps of busy50: median %.1f ms, p99 %.1f ms, worst %.1f "
      "ms over %zu calls; the step advanced %.1f s of sim time in %.1f s; ~bricks at %.1f Hz\n",
      ros_adapter::kMaxStepsPerRequest, 1e3 * median, 1e3 * p99, 1e3 * worst, latencies.size(),
      simulated, window, rate);
  EXPECT_LT(p99, kMaxP99Latency);
  // The step is not starved by the calls: it gets most of the node.
  EXPECT_GT(simulated, 0.5) << "sim time hardly advanced during the step";
  // publish_rate (30 Hz) of wall time, not of sim time (which runs faster).
  double publish_rate = 0.0;
  ASSERT_TRUE(ros::param::get(sim_->resolve(ros_adapter::kPublishRateParameter), publish_rate));
  EXPECT_GT(rate, 0.5 * publish_rate);
  EXPECT_LT(rate, 1.5 * publish_rate);
  EXPECT_GT(simulated / window, 1.5)
      << "sim time ran no faster than wall time: the wall-time check of ~bricks proves nothing";
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_responsiveness");
}
