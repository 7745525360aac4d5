// The client library against stand-ins of the node's services and topics in
// this process, under a namespace of their own: a missing service is
// reported as such after the wait, the node's refusal comes through
// unchanged, a failed transport is told apart from a refusal and tried once
// more, and a persistent connection that drops is made again.
#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "brick_stack_sim/client/sim_client.h"
#include "brick_stack_sim/ros/interface_names.h"
#include "ros/rostest/node_fixture.h"

namespace {

using namespace brick_stack_sim;

constexpr char kFakeNamespace[] = "/fake_sim";

client::ClientOptions fakeOptions(bool persistent = true) {
  client::ClientOptions options;
  options.sim_namespace = kFakeNamespace;
  options.service_wait = 2.0;
  options.persistent = persistent;
  return options;
}

/// A stand-in for the node's ~get_bricks: answers `success` and `message`,
/// or fails the call (its handler returns false) while `fail` is set.
class FakeGetBricks {
 public:
  FakeGetBricks() { advertise(); }

  void advertise() {
    ros::NodeHandle nh(kFakeNamespace);
    server_ = nh.advertiseService<GetBricks::Request, GetBricks::Response>(
        ros_adapter::kGetBricksService, [this](GetBricks::Request&, GetBricks::Response& response) {
          ++calls;
          response.success = success;
          response.message = message;
          response.bricks.resize(2);
          return !fail;
        });
  }
  void shutdown() { server_.shutdown(); }

  std::atomic<int> calls{0};
  std::atomic<bool> success{true};
  std::atomic<bool> fail{false};
  std::string message = "2 bricks";

 private:
  ros::ServiceServer server_;
};

/// Polls `done` for up to `seconds` of wall time (callbacks run in the spinner).
bool waitFor(const std::function<bool()>& done, double seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (!done()) {
    if (ros::WallTime::now() >= end) return false;
    ros::WallDuration(0.01).sleep();
  }
  return true;
}

class SimClientTest : public ::testing::Test {
 protected:
  FakeGetBricks fake_;
};

TEST_F(SimClientTest, AServiceThatIsNotThereIsReportedAfterTheWait) {
  client::ClientOptions options = fakeOptions();
  options.sim_namespace = "/no_sim_here";
  options.service_wait = 0.2;
  client::SimClient sim(options);
  const ros::WallTime start = ros::WallTime::now();
  const auto reply = sim.getBricks();
  EXPECT_LT((ros::WallTime::now() - start).toSec(), 2.0);
  EXPECT_FALSE(reply.ok);
  EXPECT_FALSE(reply.reached);
  EXPECT_EQ(reply.service, "/no_sim_here/get_bricks");
  EXPECT_EQ(reply.message, "service /no_sim_here/get_bricks not available after 0.2 s");
  const client::CallResult up = sim.waitForNode(0.1);
  EXPECT_FALSE(up.ok);
  EXPECT_NE(up.message.find("not available after 0.1 s"), std::string::npos) << up.message;
}

TEST_F(SimClientTest, AnAcceptedCallGivesTheResponse) {
  client::SimClient sim(fakeOptions());
  const auto reply = sim.getBricks({"a", "b"});
  EXPECT_TRUE(reply.ok);
  EXPECT_TRUE(reply.reached);
  EXPECT_TRUE(static_cast<bool>(reply));
  EXPECT_EQ(reply.message, "2 bricks");
  EXPECT_EQ(reply.response.bricks.size(), 2u);
}

TEST_F(SimClientTest, ARefusalIsReachedWithTheNodesMessageUnchanged) {
  fake_.success = false;
  fake_.message = "get_bricks: no brick 'x' (ids: a, b)";
  client::SimClient sim(fakeOptions());
  const auto reply = sim.getBricks({"x"});
  EXPECT_FALSE(reply.ok);
  EXPECT_TRUE(reply.reached);
  EXPECT_EQ(reply.message, fake_.message);
  EXPECT_EQ(reply.response.message, fake_.message);
  EXPECT_EQ(fake_.calls.load(), 1) << "a refusal was retried";
}

TEST_F(SimClientTest, AFailedTransportIsToldApartFromARefusalAndTriedOnceMore) {
  fake_.fail = true;
  for (bool persistent : {true, false}) {
    fake_.calls = 0;
    client::SimClient sim(fakeOptions(persistent));
    const auto reply = sim.getBricks();
    EXPECT_FALSE(reply.ok) << persistent;
    EXPECT_FALSE(reply.reached) << persistent;
    EXPECT_NE(reply.message.find("failed in transport"), std::string::npos) << reply.message;
    EXPECT_NE(reply.message.find("/fake_sim/get_bricks"), std::string::npos) << reply.message;
    EXPECT_EQ(fake_.calls.load(), 2)
        << "persistent " << persistent << ": not tried exactly once more";
  }
}

TEST_F(SimClientTest, APersistentConnectionThatDroppedIsMadeAgain) {
  client::SimClient sim(fakeOptions());
  ASSERT_TRUE(sim.getBricks().ok);
  // The server goes and comes back: the old connection is dead.
  fake_.shutdown();
  ros::WallDuration(0.2).sleep();
  fake_.advertise();
  const auto reply = sim.getBricks();
  EXPECT_TRUE(reply.ok) << reply.message;
  EXPECT_EQ(fake_.calls.load(), 2);
}

TEST_F(SimClientTest, NamesResolveUnderTheNamespaceAndTheClockStaysGlobal) {
  client::SimClient sim(fakeOptions());
  EXPECT_EQ(sim.resolve(ros_adapter::kBricksTopic), "/fake_sim/bricks");
  EXPECT_EQ(sim.resolve(ros_adapter::kClockTopic), ros_adapter::kClockTopic);
  client::ClientOptions slash = fakeOptions();
  slash.sim_namespace = "/fake_sim/";
  EXPECT_EQ(client::SimClient(slash).resolve(ros_adapter::kStepService), "/fake_sim/step");
  EXPECT_EQ(client::SimClient().resolve(ros_adapter::kStepService),
            std::string(ros_adapter::kDefaultNamespace) + "/step");
}

TEST_F(SimClientTest, TopicsGoThroughTheNamespace) {
  client::SimClient sim(fakeOptions());
  ros::NodeHandle nh(kFakeNamespace);
  std::mutex mutex;
  std::optional<geometry_msgs::PoseStamped> target;
  int bricks = 0;
  ros::Subscriber target_sub = nh.subscribe<geometry_msgs::PoseStamped>(
      ros_adapter::kHeldTargetTopic, 10, [&](const geometry_msgs::PoseStamped::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        target = *msg;
      });
  ros::Publisher bricks_pub = nh.advertise<BrickArray>(ros_adapter::kBricksTopic, 10);
  ros::Subscriber bricks_sub = sim.subscribeBricks(
      [&](const BrickArray::ConstPtr&) {
        std::lock_guard<std::mutex> lock(mutex);
        ++bricks;
      },
      10);
  const ros::Publisher& target_pub = sim.advertiseHeldTarget();
  ASSERT_TRUE(waitFor(
      [&] { return target_pub.getNumSubscribers() > 0 && bricks_pub.getNumSubscribers() > 0; },
      10.0));
  geometry_msgs::Pose pose;
  pose.position.z = 0.1;
  pose.orientation.w = 1.0;
  sim.publishHeldTarget(pose);
  bricks_pub.publish(BrickArray());
  ASSERT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return target && bricks > 0;
      },
      10.0));
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(target->header.frame_id, ros_adapter::kWorldFrame);
  EXPECT_EQ(target->pose.position.z, 0.1);
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_sim_client");
}
